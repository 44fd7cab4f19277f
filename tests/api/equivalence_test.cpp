// The API's results are collidePair's: every pair of the generated suite (and the same pairs
// moved by a pose) collided through recode::collide and through core::collidePair in the frame
// the API chose, verdicts and contact regions compared exactly. One difference is by design:
// the API, like `recode run`, draws only block pairs whose boxes (AABBs, then OBBs) overlap, so
// blocks a hair apart that collidePair sees touch within depth rounding (verification.md, rule
// (b)) are apart for the API; such pairs must really be apart (GJK distance above 0).
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "recode/api/collision.hpp"
#include "recode/geometry/convex_distance.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/pair_suite.hpp"

namespace {

using namespace recode;

// collidePair on the world meshes, in the frame the API would choose for their boxes; a pair
// whose boxes do not overlap cannot interfere and is not drawn.
core::PairResult direct(const core::TriangleMesh& a, const core::TriangleMesh& b,
                        const CollisionRequest& request) {
  const core::Aabb ba = core::boundingBox(a), bb = core::boundingBox(b);
  core::PairRequest pair;
  pair.frame = chooseFrame(ba, bb, request);
  pair.mor = request.mor;
  pair.contact = request.contact;
  raster::CpuDevice device(pair.frame.width, pair.frame.height);
  return core::collidePair(device, a, b, pair);
}

// Returns whether the pair was one the boxes kept apart.
bool requireSame(const CollisionResult& api, const core::PairResult& expected,
                 const core::TriangleMesh& a, const core::TriangleMesh& b) {
  if (api.blockPairsDrawn == 0 && expected.collide) {
    CHECK_FALSE(api.collide);
    CHECK(core::convexHullDistance(a.vertices, b.vertices) > 0.0);
    return true;
  }
  REQUIRE(api.collide == expected.collide);
  if (!expected.collide)
    return false;
  REQUIRE(api.contacts.size() == 1);
  const core::PairResult& got = api.contacts.front().pair;
  CHECK(got.caseCounts == expected.caseCounts);
  CHECK(api.interferingPixels == expected.interferingPixels);
  CHECK(api.contact.points == expected.contact.points);
  CHECK(api.contact.box.min == expected.contact.box.min);
  CHECK(api.contact.box.max == expected.contact.box.max);
  CHECK(api.contact.area == expected.contact.area);
  CHECK(api.contact.maxDepth == expected.contact.maxDepth);
  return false;
}

CollisionObject objectOf(const core::TriangleMesh& mesh, const std::string& name,
                         const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity()) {
  return CollisionObject(CollisionGeometry::single(ConvexBlock::fromMesh(mesh, name)), pose);
}

}  // namespace

TEST_CASE("the generated pair suite gives collidePair's results through the API") {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  int collisions = 0, keptApart = 0;
  for (const AxisChoice axis : {AxisChoice::Z, AxisChoice::Auto}) {
    for (const verify::SuitePair& p : suite) {
      INFO(p.label);
      CollisionRequest request;
      request.axis = axis;
      // The suite's own pixel size with its axis; 64 pixels over the overlap with auto.
      if (axis != AxisChoice::Auto)
        request.pixelSize = (p.frame.window.umax - p.frame.window.umin) / p.frame.width;
      else
        request.resolution = 64;
      CollisionResult result;
      collide(objectOf(p.a, "a"), objectOf(p.b, "b"), request, result);
      keptApart += requireSame(result, direct(p.a, p.b, request), p.a, p.b) ? 1 : 0;
      collisions += result.collide ? 1 : 0;
    }
  }
  CHECK(collisions > 200);  // the comparison is not vacuous
  CHECK(keptApart < 20);    // and the exception stays one
}

TEST_CASE("a pose set on the object gives collidePair's result on the moved mesh") {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite({.count = 70});
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), shift(-2.0, 2.0);
  for (const verify::SuitePair& p : suite) {
    INFO(p.label);
    // The same rigid motion applied to both blocks: b is placed by its own pose.
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translate(Eigen::Vector3d(shift(random), shift(random), shift(random)));
    pose.rotate(Eigen::AngleAxisd(angle(random), Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
    CollisionRequest request;
    request.resolution = 48;
    CollisionResult result;
    collide(objectOf(p.a, "a", pose), objectOf(p.b, "b", pose), request, result);
    const core::TriangleMesh a = core::transformed(p.a, pose), b = core::transformed(p.b, pose);
    (void)requireSame(result, direct(a, b, request), a, b);
  }
}
