#include "recode/geometry/mesh.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace recode::core {

Aabb boundingBox(const TriangleMesh& mesh) {
  Aabb box;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    box.extend(p);
  }
  return box;
}

namespace {

TriangleMesh transformedImpl(const TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                             const Eigen::Vector3d& translation) {
  TriangleMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices) {
    out.vertices.emplace_back(linear * p + translation);
  }
  out.triangles = mesh.triangles;
  if (linear.determinant() < 0.0) {
    for (Triangle& t : out.triangles) {
      std::swap(t[1], t[2]);
    }
  }
  return out;
}

}  // namespace

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& transform) {
  return transformedImpl(mesh, transform.linear(), transform.translation());
}

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Affine3d& transform) {
  return transformedImpl(mesh, transform.linear(), transform.translation());
}

double signedVolume(const TriangleMesh& mesh) {
  const Eigen::Vector3d origin = boundingBox(mesh).center();
  const std::size_t n = mesh.vertices.size();
  double sixTimesVolume = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (VertexIndex i : tri) {
      if (i >= n) {
        throw std::out_of_range("signedVolume: triangle " + std::to_string(t) +
                                " has vertex index " + std::to_string(i) + " out of range (" +
                                std::to_string(n) + " vertices)");
      }
    }
    const Eigen::Vector3d a = mesh.vertices[tri[0]] - origin;
    const Eigen::Vector3d b = mesh.vertices[tri[1]] - origin;
    const Eigen::Vector3d c = mesh.vertices[tri[2]] - origin;
    sixTimesVolume += a.dot(b.cross(c));
  }
  return sixTimesVolume / 6.0;
}

}  // namespace recode::core
