// The convex hull's entry points: the checks that the points span a volume (each degenerate
// case named in the message), the two exact steps (convex_hull_quick.cpp, then
// convex_hull_facets.cpp) and the renumbering onto the extreme points.

#include "recode/geometry/convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "convex_hull_detail.hpp"
#include "format.hpp"
#include "recode/geometry/exact_predicates.hpp"

namespace recode::core {
namespace {

[[noreturn]] void fail(std::string_view sourceName, const std::string& problem) {
  throw MeshError(std::string(sourceName) + ": " + problem);
}

std::string pointsText(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " point" : " points");
}

// The rule every degenerate case breaks, said once.
constexpr const char* kRule = "a convex hull needs at least 4 points that do not lie in one plane";

// Throws unless the points are finite and span a volume.
void checkSpansVolume(std::span<const Eigen::Vector3d> points, std::string_view sourceName) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!points[i].allFinite())
      fail(sourceName, "convex hull: point " + std::to_string(i) + " " +
                           detail::formatPoint(points[i]) + " has a non-finite coordinate");
    if (points[i].cwiseAbs().maxCoeff() > kMaxExactCoordinate)
      throw std::invalid_argument(std::string(sourceName) + ": convex hull: point " +
                                  std::to_string(i) + " has a coordinate beyond 1e100");
  }
  if (n < 4)
    fail(sourceName, "convex hull: only " + pointsText(n) + " (" + kRule + ")");
  if (n > std::numeric_limits<VertexIndex>::max())
    fail(sourceName, "convex hull: " + pointsText(n) + ", more than the vertex index allows");
  const Eigen::Vector3d& a = points[0];
  const auto other =
      std::find_if(points.begin(), points.end(), [&](const Eigen::Vector3d& q) { return q != a; });
  if (other == points.end())
    fail(sourceName, "convex hull: all " + pointsText(n) + " are the same point " +
                         detail::formatPoint(a) + " (" + kRule + ")");
  const Eigen::Vector3d& b = *other;
  const auto offLine = std::find_if(points.begin(), points.end(),
                                    [&](const Eigen::Vector3d& q) { return !collinear(a, b, q); });
  if (offLine == points.end())
    fail(sourceName, "convex hull: all " + pointsText(n) + " lie on one line (" + kRule + ")");
  const Eigen::Vector3d& c = *offLine;
  const bool flat = std::all_of(points.begin(), points.end(), [&](const Eigen::Vector3d& q) {
    return orient3d(a, b, c, q) == 0;
  });
  if (flat)
    fail(sourceName, "convex hull: all " + pointsText(n) + " lie in one plane (" + kRule + ")");
}

}  // namespace

ConvexHull convexHull(std::span<const Eigen::Vector3d> points, std::string_view sourceName) {
  checkSpansVolume(points, sourceName);
  const std::vector<Triangle> triangles =
      detail::cornerTriangulation(points, detail::quickHullTriangles(points));

  // Renumber onto the extreme points, in input order.
  ConvexHull hull;
  std::vector<VertexIndex> newIndex(points.size(), std::numeric_limits<VertexIndex>::max());
  for (const Triangle& t : triangles) {
    for (const VertexIndex v : t)
      newIndex[v] = 0;
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (newIndex[i] == 0) {
      newIndex[i] = static_cast<VertexIndex>(hull.mesh.vertices.size());
      hull.mesh.vertices.push_back(points[i]);
      hull.inputIndex.push_back(i);
    }
  }
  hull.mesh.triangles.reserve(triangles.size());
  for (const Triangle& t : triangles)
    hull.mesh.triangles.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});
  return hull;
}

}  // namespace recode::core
