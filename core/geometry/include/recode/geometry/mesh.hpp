#pragma once
// Indexed triangle meshes, the geometry every convex block is made of.
//
// Conventions (see docs/geometry.md): vertices are points in a right-handed frame;
// triangles index into `vertices`; a closed mesh's triangles are counter-clockwise when
// seen from outside, so the normal (b - a) x (c - a) of triangle (a, b, c) points outward
// and the signed volume of a well-formed closed mesh is positive.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "recode/raster/vertex_stage.hpp"

namespace recode::core {

// The position of a vertex in TriangleMesh::vertices.
using VertexIndex = std::uint32_t;
// Three vertex indices, counter-clockwise seen from outside a closed mesh.
using Triangle = std::array<VertexIndex, 3>;

// An axis-aligned box. The default value is empty (min = +inf, max = -inf), so that
// extending it by a point gives that point's box.
struct Aabb {
  // The smallest x, y, z (+inf in an empty box).
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  // The largest x, y, z (-inf in an empty box).
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  // True if no point has been added (any min component above the max component).
  [[nodiscard]] bool isEmpty() const { return (min.array() > max.array()).any(); }
  // Grows the box to contain p.
  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  // Grows the box to contain `other`; an empty `other` leaves it as it is (extending by its
  // corners instead would not: an empty box's corners are infinities).
  void extend(const Aabb& other) {
    min = min.cwiseMin(other.min);
    max = max.cwiseMax(other.max);
  }
  // max - min; meaningless for an empty box.
  [[nodiscard]] Eigen::Vector3d extent() const { return max - min; }
  // (min + max) / 2; meaningless for an empty box.
  [[nodiscard]] Eigen::Vector3d center() const { return 0.5 * (min + max); }
  // Length of the box's diagonal, 0 for an empty box.
  [[nodiscard]] double diagonal() const { return isEmpty() ? 0.0 : extent().norm(); }
};

// A mesh of triangles over shared vertices (the conventions above).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;  // points, indexed by the triangles
  std::vector<Triangle> triangles;        // indices into vertices

  // vertices.size()
  [[nodiscard]] std::size_t vertexCount() const { return vertices.size(); }
  // triangles.size()
  [[nodiscard]] std::size_t triangleCount() const { return triangles.size(); }
};

// The largest absolute coordinate of a mesh that can be drawn: every vertex finite, every
// index below vertexCount() and at least one triangle; infinity for any other mesh.
[[nodiscard]] double drawableExtent(const TriangleMesh& mesh);

// Box of all vertices (referenced by a triangle or not). Empty for a mesh without
// vertices. Non-finite coordinates propagate into the box as the min/max operations give.
[[nodiscard]] Aabb boundingBox(const TriangleMesh& mesh);

// The pose (linear, translation) as the vertex stage of the rasterization contract takes it
// (raster::Pose: the linear part row by row).
[[nodiscard]] inline raster::Pose rasterPose(const Eigen::Matrix3d& linear,
                                             const Eigen::Vector3d& translation) {
  raster::Pose pose;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      pose.linear[static_cast<std::size_t>(3 * r + c)] = linear(r, c);
    pose.translation[static_cast<std::size_t>(r)] = translation(r);
  }
  return pose;
}

// linear * v + translation by the contract's vertex stage (raster::poseVertex: each product and
// sum rounded on its own, rows x and y as ((l0 v0 + l1 v1) + l2 v2) + t, row z as
// (l0 v0 + (l1 v1 + l2 v2)) + t, the order Eigen's Matrix3d * Vector3d took in the baseline
// x86-64 build every golden result was made with). A SIMD loop can repeat it lane for lane
// (core/sim's posed vertex box). Code that calls it gets those bits only when it is built without
// contraction, as everything linking recode_raster is.
[[nodiscard]] inline Eigen::Vector3d posedPoint(const raster::Pose& pose,
                                                const Eigen::Vector3d& v) {
  const std::array<double, 3> w = raster::poseVertex(pose, {v.x(), v.y(), v.z()});
  return {w[0], w[1], w[2]};
}
// posedPoint with the pose as Eigen's linear part and translation.
[[nodiscard]] inline Eigen::Vector3d posedPoint(const Eigen::Matrix3d& linear,
                                                const Eigen::Vector3d& translation,
                                                const Eigen::Vector3d& v) {
  return posedPoint(rasterPose(linear, translation), v);
}

// A copy with every vertex mapped by `transform` (posedPoint). The triangles are copied unchanged,
// except that when the transform's linear part has a negative determinant (a reflection) each
// triangle's last two indices are swapped, so outward faces stay outward.
[[nodiscard]] TriangleMesh transformed(const TriangleMesh& mesh,
                                       const Eigen::Isometry3d& transform);
// The same for an affine map, which may also scale or shear.
[[nodiscard]] TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Affine3d& transform);
// transformed(mesh, transform) written into `out`, reusing its storage: the same vertices bit
// for bit (the same arithmetic), and the triangles copied only when `out` does not already hold
// them as transformed() would give them. For a caller that maps one mesh frame after frame.
// `out` must not be `mesh`.
void transformInto(const TriangleMesh& mesh, const Eigen::Isometry3d& transform, TriangleMesh& out);

// Signed volume enclosed by the triangles (divergence theorem: the sum over triangles of
// det(a - o, b - o, c - o) / 6, with o the bounding-box centre for accuracy). Positive for
// a closed, outward-oriented mesh; meaningful only for closed meshes. Throws
// std::out_of_range if a triangle index is not below vertexCount().
[[nodiscard]] double signedVolume(const TriangleMesh& mesh);

}  // namespace recode::core
