// The generated pair suite is itself checked: deterministic, spread over its configurations,
// every block a valid convex block, every frame covering both blocks, and the configurations
// being what their names say where that can be checked without an oracle.

#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "recode/geometry/validate.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/view.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

namespace {

bool sameMesh(const core::TriangleMesh& x, const core::TriangleMesh& y) {
  return x.vertices == y.vertices && x.triangles == y.triangles;
}

// Largest signed distance of any of `points`' vertices beyond the face planes of the convex
// block `hull` (<= 0: all inside or on it).
double worstOutside(const core::TriangleMesh& hull, const core::TriangleMesh& points) {
  double worst = -INFINITY;
  for (const core::Triangle& t : hull.triangles) {
    const Eigen::Vector3d a = hull.vertices[t[0]], b = hull.vertices[t[1]], c = hull.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    for (const Eigen::Vector3d& p : points.vertices)
      worst = std::max(worst, n.dot(p - a));
  }
  return worst;
}

}  // namespace

TEST_CASE("pair suite: the same options give the same pairs") {
  verify::PairSuiteOptions options;
  options.count = 40;
  const auto first = verify::generatePairSuite(options);
  const auto second = verify::generatePairSuite(options);
  REQUIRE(first.size() == 40);
  REQUIRE(second.size() == 40);
  for (std::size_t i = 0; i < first.size(); ++i) {
    CHECK(first[i].label == second[i].label);
    CHECK(sameMesh(first[i].a, second[i].a));
    CHECK(sameMesh(first[i].b, second[i].b));
  }
  options.seed += 1;
  const auto other = verify::generatePairSuite(options);
  int differing = 0;
  for (std::size_t i = 0; i < first.size(); ++i)
    differing += sameMesh(first[i].b, other[i].b) ? 0 : 1;
  CHECK(differing == 40);
}

TEST_CASE("pair suite: 504 pairs, 72 per configuration, unique labels, valid blocks, frames") {
  const auto suite = verify::generatePairSuite();
  REQUIRE(suite.size() == 504);
  std::map<verify::PairConfiguration, int> perConfiguration;
  std::set<std::string> labels;
  std::set<core::ViewAxis> axes;
  for (const verify::SuitePair& pair : suite) {
    ++perConfiguration[pair.configuration];
    labels.insert(pair.label);
    axes.insert(pair.frame.axis);
    INFO(pair.label);
    CHECK(core::checkConvexBlock(pair.a).ok());
    CHECK(core::checkConvexBlock(pair.b).ok());
    CHECK(pair.frame.width == 64);
    // Both blocks project inside the window, so nothing is cut off at the frame's border.
    const auto depth =
        core::pairDepthRange(pair.frame.axis, core::boundingBox(pair.a), core::boundingBox(pair.b));
    const core::OrthoView view(pair.frame.axis, pair.frame.window, pair.frame.width,
                               pair.frame.height, depth[0], depth[1]);
    for (const core::TriangleMesh* m : {&pair.a, &pair.b})
      for (const Eigen::Vector3d& p : m->vertices) {
        const raster::WindowVertex w = view.toWindow(p);
        CHECK(w.x > 0.0f);
        CHECK(w.y > 0.0f);
        CHECK(w.x < static_cast<float>(pair.frame.width));
        CHECK(w.y < static_cast<float>(pair.frame.height));
      }
  }
  CHECK(labels.size() == suite.size());
  CHECK(axes.size() == 3);
  REQUIRE(perConfiguration.size() == verify::kPairConfigurationCount);
  for (const auto& [configuration, n] : perConfiguration)
    CHECK(n == 72);
}

TEST_CASE("pair suite: configurations are what they say") {
  const auto suite = verify::generatePairSuite();
  int exactTips = 0;
  for (const verify::SuitePair& pair : suite) {
    INFO(pair.label);
    if (pair.configuration == verify::PairConfiguration::Inside) {
      // One block lies inside the other: all its vertices within the other's face planes.
      const double aInB = worstOutside(pair.b, pair.a), bInA = worstOutside(pair.a, pair.b);
      CHECK(std::min(aInB, bInA) < -0.01);
    }
    if (pair.configuration == verify::PairConfiguration::TipOnTip) {
      // The apexes (last vertex of each cone) are a gap apart; on exact placements with gap 0
      // they coincide bit for bit.
      const double distance = (pair.a.vertices.back() - pair.b.vertices.back()).norm();
      CHECK(distance <= 0.05 + 1e-12);
      if (pair.a.vertices.back() == pair.b.vertices.back())
        ++exactTips;
    }
  }
  // Gap 0 comes every 7th round and exact placement every 2nd: rounds 0, 14, 28, ... of 72.
  CHECK(exactTips >= 5);
}

TEST_CASE("pair suite: bad options are rejected with the option named") {
  verify::PairSuiteOptions options;
  options.count = 0;
  CHECK_THROWS_WITH(verify::generatePairSuite(options), Catch::Contains("count"));
  options.count = 10;
  options.width = 0;
  CHECK_THROWS_WITH(verify::generatePairSuite(options), Catch::Contains("width"));
}
