// The convex hull as a convex block. The exact hull can hold triangles that the block
// validation refuses as degenerate: two corners a few units in the last place apart, or a
// corner a hair off the line between two others (a rotated grid's edge, after rounding). Such a
// corner lies within the tolerance of the segment opposite it, so of the hull of the other
// points: it is dropped and the hull made again, until no triangle is thinner than the
// tolerance. Each drop moves the surface by at most the tolerance. The result is then validated
// like every block.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "recode/geometry/convex_hull.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core {
namespace {

constexpr double kRelativeTolerance = 1e-9;  // validateConvexBlock's default
// Drop a little more than the validation refuses, so rounding in the two height computations
// cannot leave a triangle that validation then refuses.
constexpr double kDropMargin = 1.01;

// For a triangle whose height over its longest edge is at most `tol`: the corner opposite that
// edge (local index 0..2); -1 for a triangle thick enough.
int thinCorner(const TriangleMesh& mesh, const Triangle& t, double tol) {
  int longest = 0;
  double longestLength = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double length = (mesh.vertices[t[static_cast<std::size_t>((k + 1) % 3)]] -
                           mesh.vertices[t[static_cast<std::size_t>(k)]])
                              .norm();
    if (length > longestLength) {
      longestLength = length;
      longest = k;
    }
  }
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  const double twiceArea = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  const double height = twiceArea / longestLength;
  return height <= tol ? (longest + 2) % 3 : -1;
}

std::string pointsText(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " point" : " points");
}

}  // namespace

TriangleMesh convexHullBlock(std::span<const Eigen::Vector3d> points, std::string_view sourceName) {
  const std::string prefix = std::string(sourceName) + ": the convex hull of its " +
                             pointsText(points.size()) + " is not a valid convex block (";
  const std::string rule =
      "); its points are too close to one plane, line or point for the validation tolerance";
  ConvexHull hull = convexHull(points, sourceName);
  std::vector<Eigen::Vector3d> kept;
  for (;;) {
    const double tol = kDropMargin * kRelativeTolerance * boundingBox(hull.mesh).diagonal();
    // Corners to drop this round; at most one per triangle, so that of two corners a hair
    // apart one stays.
    std::vector<bool> drop(hull.mesh.vertexCount(), false);
    std::vector<bool> touched(hull.mesh.vertexCount(), false);
    bool any = false;
    for (const Triangle& t : hull.mesh.triangles) {
      const int corner = thinCorner(hull.mesh, t, tol);
      if (corner < 0)
        continue;
      const VertexIndex v = t[static_cast<std::size_t>(corner)];
      if (touched[t[0]] || touched[t[1]] || touched[t[2]])
        continue;
      drop[v] = true;
      any = true;
      for (const VertexIndex w : t)
        touched[w] = true;
    }
    if (!any)
      break;
    kept.clear();
    for (std::size_t k = 0; k < hull.mesh.vertexCount(); ++k) {
      if (!drop[k])
        kept.push_back(hull.mesh.vertices[k]);
    }
    try {
      hull = convexHull(kept, sourceName);
    } catch (const MeshError& e) {
      // Too few corners left: the points span no volume at the tolerance.
      const std::string what = e.what();
      throw MeshError(prefix + what.substr(std::min(what.size(), sourceName.size() + 2)) + rule);
    }
  }
  const ValidationReport report = checkConvexBlock(hull.mesh, kRelativeTolerance, 1);
  if (!report.ok())
    throw MeshError(prefix + report.problems.front().message + rule);
  return std::move(hull.mesh);
}

}  // namespace recode::core
