// The manager: ids, moves, removal, and results equal to collide() on each pair.
#include <catch2/catch.hpp>

#include <memory>

#include "recode/api/manager.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/pair/pair_result_compare.hpp"

namespace {

using namespace recode;

std::shared_ptr<CollisionObject> sphereAt(double x, double y) {
  static const CollisionGeometryPtr sphere =
      CollisionGeometry::single(ConvexBlock::fromMesh(core::makeSphere(0.5, 16, 8), "sphere"));
  return std::make_shared<CollisionObject>(sphere,
                                           Eigen::Isometry3d(Eigen::Translation3d(x, y, 0.0)));
}

}  // namespace

TEST_CASE("the manager finds the pairs in contact with collide()'s results") {
  CollisionManager manager;
  std::vector<std::shared_ptr<CollisionObject>> objects;
  // A row of spheres 0.8 apart: neighbours overlap, others do not.
  for (int i = 0; i < 6; ++i) {
    objects.push_back(sphereAt(0.8 * i, 0.0));
    CHECK(manager.add(objects.back()) == i);
  }
  CollisionRequest request;
  request.pixelSize = 0.02;
  std::vector<ObjectContact> contacts = manager.collide(request);
  REQUIRE(contacts.size() == 5);
  CHECK(manager.stats().candidatePairs == 5);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    CHECK(contacts[k].a == static_cast<ObjectId>(k));
    CHECK(contacts[k].b == static_cast<ObjectId>(k + 1));
    CollisionResult alone;
    REQUIRE(collide(*objects[k], *objects[k + 1], request, alone));
    CHECK(alone.contact.points == contacts[k].result.contact.points);
  }

  // Move sphere 5 away, remove sphere 2: pairs (0,1) and (3,4) remain.
  manager.update(5, Eigen::Isometry3d(Eigen::Translation3d(10.0, 0.0, 0.0)));
  manager.remove(2);
  CHECK(manager.size() == 5);
  contacts = manager.collide(request);
  REQUIRE(contacts.size() == 2);
  CHECK((contacts[0].a == 0 && contacts[0].b == 1));
  CHECK((contacts[1].a == 3 && contacts[1].b == 4));
  CHECK_THROWS_AS(manager.remove(2), std::out_of_range);
  CHECK_THROWS_AS(manager.object(17), std::out_of_range);
  CHECK(manager.add(sphereAt(0.0, 0.4)) == 6);  // ids are not reused

  int calls = 0;
  manager.collide(request, [&](ObjectId, ObjectId, const CollisionResult& r) {
    ++calls;
    CHECK(r.collide);
  });
  CHECK(calls == 4);  // (0,1), (3,4), (0,6), (1,6)
}

TEST_CASE("the manager's block pairs on threads give the answers decided in turn") {
  // Two rows of spheres, neighbours overlapping, several block pairs per call; every mode.
  std::vector<std::shared_ptr<CollisionObject>> objects;
  for (int i = 0; i < 8; ++i)
    objects.push_back(sphereAt(0.8 * (i % 4), 0.7 * (i / 4)));
  for (const core::PairMode mode : {core::PairMode::Reference, core::PairMode::Conservative,
                                    core::PairMode::Adaptive, core::PairMode::SkipApart}) {
    INFO("mode " << core::toString(mode));
    CollisionRequest request;
    request.pixelSize = 0.02;
    request.mode = mode;
    request.normal = true;
    CollisionManager inTurn, onThreads;
    for (const auto& object : objects) {
      (void)inTurn.add(object);
      (void)onThreads.add(object);
    }
    const std::vector<ObjectContact> expected = inTurn.collide(request);
    request.threads = 0;
    const std::vector<ObjectContact> got = onThreads.collide(request);
    REQUIRE(expected.size() >= 8);
    REQUIRE(got.size() == expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      CHECK(got[k].a == expected[k].a);
      CHECK(got[k].b == expected[k].b);
      REQUIRE(got[k].result.contacts.size() == expected[k].result.contacts.size());
      for (std::size_t c = 0; c < got[k].result.contacts.size(); ++c)
        CHECK(core::firstDifference(got[k].result.contacts[c].pair,
                                    expected[k].result.contacts[c].pair)
                  .value_or("") == "");
      CHECK(got[k].result.contact.points == expected[k].result.contact.points);
    }
  }
}

TEST_CASE("a negative thread count is refused") {
  CollisionRequest request;
  request.threads = -2;
  CollisionResult result;
  CHECK_THROWS_WITH(collide(*sphereAt(0, 0), *sphereAt(0.5, 0), request, result),
                    "CollisionRequest::threads is -2: give 1 (the caller's thread), 0 (every "
                    "hardware thread) or a count");
}
