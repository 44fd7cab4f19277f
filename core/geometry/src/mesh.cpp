#include "recode/geometry/mesh.hpp"

#include <algorithm>
#include <limits>
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

double drawableExtent(const TriangleMesh& mesh) {
  constexpr double kNotDrawable = std::numeric_limits<double>::infinity();
  if (mesh.triangles.empty())
    return kNotDrawable;
  double largest = 0.0;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    if (!p.allFinite())
      return kNotDrawable;
    largest = std::max(largest, p.cwiseAbs().maxCoeff());
  }
  const std::size_t n = mesh.vertices.size();
  for (const Triangle& t : mesh.triangles)
    if (t[0] >= n || t[1] >= n || t[2] >= n)
      return kNotDrawable;
  return largest;
}

namespace {

// Whether the triangles of `out` are those of `mesh`, with the last two indices of each swapped
// when `mirrored`.
bool sameTriangles(const TriangleMesh& mesh, bool mirrored, const TriangleMesh& out) {
  if (out.triangles.size() != mesh.triangles.size())
    return false;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& a = mesh.triangles[t];
    const Triangle& b = out.triangles[t];
    if (a[0] != b[0] || a[1] != b[mirrored ? 2 : 1] || a[2] != b[mirrored ? 1 : 2])
      return false;
  }
  return true;
}

void transformIntoImpl(const TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                       const Eigen::Vector3d& translation, TriangleMesh& out) {
  out.vertices.resize(mesh.vertices.size());
  const raster::Pose pose = rasterPose(linear, translation);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    out.vertices[i] = posedPoint(pose, mesh.vertices[i]);
  const bool mirrored = linear.determinant() < 0.0;
  if (sameTriangles(mesh, mirrored, out))
    return;
  out.triangles = mesh.triangles;
  if (mirrored) {
    for (Triangle& t : out.triangles) {
      std::swap(t[1], t[2]);
    }
  }
}

TriangleMesh transformedImpl(const TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                             const Eigen::Vector3d& translation) {
  TriangleMesh out;
  transformIntoImpl(mesh, linear, translation, out);
  return out;
}

}  // namespace

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& transform) {
  return transformedImpl(mesh, transform.linear(), transform.translation());
}

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Affine3d& transform) {
  return transformedImpl(mesh, transform.linear(), transform.translation());
}

void transformInto(const TriangleMesh& mesh, const Eigen::Isometry3d& transform,
                   TriangleMesh& out) {
  transformIntoImpl(mesh, transform.linear(), transform.translation(), out);
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
