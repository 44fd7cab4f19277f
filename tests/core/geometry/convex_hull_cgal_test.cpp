// The convex hull against CGAL's convex_hull_3 (exact kernel): on many random point sets,
// including hard ones (points on a sphere, grids with many coplanar points, rotated grids whose
// planes rounding has broken, clusters of near-duplicates), the same extreme points and exactly
// the same volume; and every hull made a block (convexHullBlock) passes the convex-block
// validation, with extreme points only and nearly the same volume. Built only with CGAL
// (RECODE_WITH_CGAL); the geometry library itself never uses it.

#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "recode/geometry/convex_hull.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;

using Key = std::array<double, 3>;

Key key(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

// The exact volume of a closed triangle mesh: the sum of signed tetrahedra from the origin.
Kernel::FT exactVolume(const TriangleMesh& mesh) {
  const Point origin(0, 0, 0);
  Kernel::FT sum = 0;
  for (const Triangle& t : mesh.triangles) {
    const auto pt = [&](VertexIndex i) {
      const Eigen::Vector3d& v = mesh.vertices[i];
      return Point(v.x(), v.y(), v.z());
    };
    sum += CGAL::volume(origin, pt(t[0]), pt(t[1]), pt(t[2]));
  }
  return sum;
}

// Compares one point set with CGAL; returns the number of extreme points.
// Counts the corners the blocks dropped, over a family.
std::size_t dropped = 0;

std::size_t compareWithCgal(const std::vector<Eigen::Vector3d>& points, const std::string& what) {
  INFO(what << ", " << points.size() << " points");
  const ConvexHull ours = convexHull(points, what);

  std::vector<Point> input;
  for (const Eigen::Vector3d& p : points)
    input.emplace_back(p.x(), p.y(), p.z());
  Surface theirs;
  CGAL::convex_hull_3(input.begin(), input.end(), theirs);

  std::vector<Key> ourKeys;
  for (const Eigen::Vector3d& v : ours.mesh.vertices)
    ourKeys.push_back(key(v));
  std::vector<Key> theirKeys;
  for (const auto v : theirs.vertices()) {
    const Point& p = theirs.point(v);
    theirKeys.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  std::sort(ourKeys.begin(), ourKeys.end());
  std::sort(theirKeys.begin(), theirKeys.end());
  REQUIRE(ourKeys == theirKeys);

  const Kernel::FT theirVolume = CGAL::Polygon_mesh_processing::volume(theirs);
  const Kernel::FT ourVolume = exactVolume(ours.mesh);
  INFO("volume " << CGAL::to_double(ourVolume) << " vs CGAL " << CGAL::to_double(theirVolume));
  REQUIRE(ourVolume == theirVolume);

  // The block: valid, made of extreme points only, its volume within what dropping corners
  // closer than the tolerance can change (each moves the surface by at most the tolerance).
  const TriangleMesh block = convexHullBlock(points, what);
  const ValidationReport report = checkConvexBlock(block);
  INFO((report.ok() ? std::string("valid") : report.problems.front().message));
  CHECK(report.ok());
  for (const Eigen::Vector3d& v : block.vertices)
    REQUIRE(std::binary_search(ourKeys.begin(), ourKeys.end(), key(v)));
  const double volume = CGAL::to_double(theirVolume);
  CHECK(std::abs(signedVolume(block) - volume) <= 1e-6 * volume);
  dropped += ourKeys.size() - block.vertexCount();
  return ourKeys.size();
}

using Generator = std::function<std::vector<Eigen::Vector3d>(std::mt19937_64&)>;

// expectDrops: the family has corners closer than the tolerance, which the blocks must drop.
void runFamily(const std::string& name, const Generator& make, int sets, bool expectDrops) {
  dropped = 0;
  std::size_t extremeTotal = 0;
  std::size_t pointTotal = 0;
  for (int seed = 0; seed < sets; ++seed) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 7919 + 1);
    const std::vector<Eigen::Vector3d> points = make(rng);
    pointTotal += points.size();
    extremeTotal += compareWithCgal(points, name + " seed " + std::to_string(seed));
  }
  // Each family has points that are not extreme, so dropping them is tested too.
  CHECK(extremeTotal < pointTotal);
  INFO(name << ": " << extremeTotal << " extreme points of " << pointTotal << ", blocks dropped "
            << dropped);
  CHECK((dropped > 0) == expectDrops);
}

TEST_CASE("hull equals CGAL's: uniform points in a box", "[hull][cgal]") {
  runFamily(
      "uniform",
      [](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(-3.0, 5.0);
        std::vector<Eigen::Vector3d> points(4 + rng() % 300);
        for (auto& p : points)
          p = {u(rng), u(rng), 0.5 * u(rng)};
        return points;
      },
      40, false);
}

TEST_CASE("hull equals CGAL's: points on a sphere", "[hull][cgal]") {
  runFamily(
      "sphere",
      [](std::mt19937_64& rng) {
        std::normal_distribution<double> g;
        std::vector<Eigen::Vector3d> points(20 + rng() % 400);
        for (auto& p : points)
          p = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 2.5;
        points.push_back(Eigen::Vector3d::Zero());  // the centre: never extreme
        return points;
      },
      40, false);
}

TEST_CASE("hull equals CGAL's: grids with many coplanar points", "[hull][cgal]") {
  runFamily(
      "grid",
      [](std::mt19937_64& rng) {
        // A random subset of a small grid, spacing 0.1 (not exact in binary, but equal indices give
        // equal coordinates, so whole planes and lines of points are exactly coplanar).
        std::vector<Eigen::Vector3d> points;
        const int side = 3 + static_cast<int>(rng() % 5);
        for (int x = 0; x < side; ++x)
          for (int y = 0; y < side; ++y)
            for (int z = 0; z < side; ++z)
              if (rng() % 3 != 0 || (x + y + z) % 5 == 0)
                points.emplace_back(0.1 * x, 0.1 * y, 0.1 * z);
        return points;
      },
      40, false);
}

TEST_CASE("hull equals CGAL's: rotated grids, planes broken by rounding", "[hull][cgal]") {
  runFamily(
      "rotated grid",
      [](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> angle(0.0, 3.0);
        const Eigen::Matrix3d r = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
        std::vector<Eigen::Vector3d> points;
        for (int x = 0; x < 5; ++x)
          for (int y = 0; y < 4; ++y)
            for (int z = 0; z < 4; ++z)
              points.push_back(r * Eigen::Vector3d(x, y, z));
        return points;
      },
      30, true);
}

TEST_CASE("hull equals CGAL's: near-duplicates and points a hair off faces", "[hull][cgal]") {
  runFamily(
      "near-duplicates",
      [](std::mt19937_64& rng) {
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::uniform_int_distribution<int> ulps(-2, 2);
        std::vector<Eigen::Vector3d> points;
        for (int i = 0; i < 40; ++i) {
          const Eigen::Vector3d base(u(rng), u(rng), u(rng));
          points.push_back(base);
          // Copies a few units in the last place away, and exact repeats.
          for (int k = 0; k < 3; ++k) {
            Eigen::Vector3d q = base;
            for (int axis = 0; axis < 3; ++axis) {
              for (int step = ulps(rng); step != 0; step += step > 0 ? -1 : 1)
                q[axis] = std::nextafter(q[axis], step > 0 ? 2.0 : -2.0);
            }
            points.push_back(q);
          }
          points.push_back(base);
        }
        return points;
      },
      30, true);
}

}  // namespace
}  // namespace recode::core
