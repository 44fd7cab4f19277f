// Blocks, shapes, objects and the frame rule of the collision API.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/validate.hpp"
#include "recode/raster/cpu_device.hpp"

namespace {

using namespace recode;

core::Aabb box(Eigen::Vector3d min, Eigen::Vector3d max) {
  core::Aabb b;
  b.min = min;
  b.max = max;
  return b;
}

CollisionGeometryPtr boxShape(double half) {
  return CollisionGeometry::single(ConvexBlock::fromMesh(core::makeBox(half, half, half), "box"));
}

}  // namespace

TEST_CASE("a block that is not a convex block is refused with the validator's message") {
  core::TriangleMesh open = core::makeBox(1.0, 1.0, 1.0);
  open.triangles.pop_back();
  std::string expected;
  try {
    core::validateConvexBlock(open, "lid");
  } catch (const core::MeshError& e) {
    expected = e.what();
  }
  REQUIRE_FALSE(expected.empty());
  CHECK_THROWS_WITH(ConvexBlock::fromMesh(open, "lid"), expected);
  CHECK_THROWS_WITH(ConvexBlock::fromArrays(open.vertices, open.triangles, "lid"), expected);
  CHECK_THROWS_AS(ConvexBlock::fromFile("no/such/file.obj"), core::MeshError);
  CHECK_THROWS_AS(CollisionGeometry::single(nullptr), std::invalid_argument);
  CHECK_THROWS_AS(CollisionObject(nullptr), std::invalid_argument);
}

TEST_CASE("auto picks the axis across the overlap's thinnest side, ties to z then x") {
  CollisionRequest request;
  request.resolution = 100;
  // Overlap 0.2 along x, 2 along y and z.
  const core::Aabb a = box({-1, -1, -1}, {0.1, 1, 1}), b = box({-0.1, -1, -1}, {1, 1, 1});
  const core::FrameSpec f = chooseFrame(a, b, request);
  CHECK(f.axis == core::ViewAxis::X);
  // 100 pixels across the overlap's longer side on the image plane (2 units).
  CHECK((f.window.umax - f.window.umin) / f.width == Approx(0.02));
  CHECK(f.width % core::kPairFrameGranule == 0);
  CHECK(chooseFrame(box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1}), request).axis ==
        core::ViewAxis::Z);
  CHECK(chooseFrame(box({0, 0, 0}, {1, 1, 2}), box({0, 0, 0}, {1, 1, 2}), request).axis ==
        core::ViewAxis::X);
  request.axis = AxisChoice::Y;
  CHECK(chooseFrame(a, b, request).axis == core::ViewAxis::Y);
  request.resolution = 0;
  CHECK_THROWS_AS(chooseFrame(a, b, request), std::invalid_argument);
}

TEST_CASE("a given pixel size draws in the frame recode run uses for the pair") {
  CollisionRequest request;
  request.pixelSize = 0.05;
  request.axis = AxisChoice::Z;
  const core::Aabb a = box({-1, -1, -1}, {0.1, 1, 1}), b = box({-0.1, -1, -1}, {1, 1, 1});
  const core::FrameSpec f = chooseFrame(a, b, request),
                        g = core::granularPairFrame(core::ViewAxis::Z, 0.05, a, b);
  CHECK(f.width == g.width);
  CHECK(f.height == g.height);
  CHECK(f.window.umin == g.window.umin);
  CHECK(f.window.vmax == g.window.vmax);
}

TEST_CASE("setTransform moves the object's world box") {
  CollisionObject o(boxShape(0.5));
  CHECK(o.worldBox().min == Eigen::Vector3d::Constant(-0.5));
  o.setTransform(Eigen::Isometry3d(Eigen::Translation3d(2.0, 0.0, 0.0)));
  CHECK(o.worldBox().min == Eigen::Vector3d(1.5, -0.5, -0.5));
  CHECK(o.transform().translation() == Eigen::Vector3d(2.0, 0.0, 0.0));
}

TEST_CASE("a compound object names the blocks in contact") {
  const ConvexBlockPtr cube = ConvexBlock::fromMesh(core::makeBox(0.5, 0.5, 0.5), "cube");
  // A dumbbell of two cubes along x, at -2 and +2.
  const CollisionGeometryPtr dumbbell =
      CollisionGeometry::compound({{cube, Eigen::Isometry3d(Eigen::Translation3d(-2.0, 0.0, 0.0))},
                                   {cube, Eigen::Isometry3d(Eigen::Translation3d(2.0, 0.0, 0.0))}},
                                  "dumbbell");
  REQUIRE(dumbbell->blockCount() == 2);
  const CollisionObject bar(dumbbell);
  // A cube pressed into the right-hand block only.
  const CollisionObject probe(boxShape(0.5),
                              Eigen::Isometry3d(Eigen::Translation3d(2.6, 0.2, 0.0)));
  CollisionRequest request;
  request.pixelSize = 0.02;
  CollisionResult result;
  REQUIRE(collide(bar, probe, request, result));
  REQUIRE(result.contacts.size() == 1);
  CHECK(result.contacts[0].blockA == 1);
  CHECK(result.contacts[0].blockB == 0);
  CHECK(result.blockPairsDrawn == 1);
  CHECK(result.contact.box.min.x() >= 2.0);
  // Both ways round: the blocks swap sides.
  REQUIRE(collide(probe, bar, request, result));
  CHECK(result.contacts[0].blockA == 0);
  CHECK(result.contacts[0].blockB == 1);
  CHECK_THROWS_AS(CollisionGeometry::compound({}), std::invalid_argument);
}

TEST_CASE("a device factory is the seam, and a wrong device is refused") {
  CollisionObject a(boxShape(0.5)),
      b(boxShape(0.5), Eigen::Isometry3d(Eigen::Translation3d(0.5, 0.0, 0.0)));
  int made = 0;
  DevicePool counting([&made](int w, int h) {
    ++made;
    return std::make_unique<raster::CpuDevice>(w, h);
  });
  CollisionResult mine, builtin;
  CollisionRequest request;
  REQUIRE(collide(a, b, request, mine, counting));
  REQUIRE(collide(a, b, request, builtin));
  CHECK(made == 1);
  CHECK(mine.contact.points == builtin.contact.points);
  REQUIRE(collide(a, b, request, mine, counting));
  CHECK(made == 1);  // the pool keeps its device

  DevicePool wrong([](int, int) { return std::make_unique<raster::CpuDevice>(8, 8); });
  CHECK_THROWS_AS(collide(a, b, request, mine, wrong), std::invalid_argument);
  DevicePool none([](int, int) { return std::unique_ptr<raster::DepthStencilDevice>(); });
  CHECK_THROWS_AS(collide(a, b, request, mine, none), std::logic_error);
}

TEST_CASE("past 16 sizes the pool reshapes the CpuDevices it dropped") {
  DevicePool pool;
  std::vector<const raster::DepthStencilDevice*> first;
  for (int k = 1; k <= 16; ++k)
    first.push_back(&pool.device(8 * k, 8));
  CHECK(pool.size() == 16);
  // The 17th size starts the pool again: the device is one of those 16, reshaped.
  const raster::DepthStencilDevice& next = pool.device(20, 20);
  CHECK(pool.size() == 1);
  CHECK(std::find(first.begin(), first.end(), &next) != first.end());
  CHECK(next.width() == 20);
  CHECK(next.height() == 20);
  CHECK(next.readStencil({0, 0, 20, 20}) == std::vector<std::uint8_t>(400, 0));
}

TEST_CASE("the request's mode: a needle thinner than a pixel is missed, refined or grown into") {
  // A square needle 1e-4 wide along z through a cube, pixels of 0.05 seen along z: no pixel
  // centre lies in the needle's cross-section (the chance is (1e-4 / 0.05)^2), so the reference
  // misses the contact; pixels 4^5 times smaller see it; the grown blocks meet at once.
  const auto needle = CollisionGeometry::single(
      ConvexBlock::fromMesh(core::makeBox(0.5e-4, 0.5e-4, 1.0), "needle"));
  CollisionObject cube(boxShape(0.5)), pin(needle);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0123, -0.0311, 0.0);
  pin.setTransform(pose);
  CollisionRequest request;
  request.pixelSize = 0.05;
  request.axis = AxisChoice::Z;
  CollisionResult result;
  CHECK_FALSE(collide(cube, pin, request, result));
  request.mode = core::PairMode::Adaptive;
  REQUIRE(collide(cube, pin, request, result));
  REQUIRE(result.contacts.size() == 1);
  CHECK(result.contacts[0].refineLevel >= 1);
  CHECK(result.contacts[0].frame.window.umax - result.contacts[0].frame.window.umin < 0.05 * 64);
  CHECK(result.apartAtLimit == 0);
  request.mode = core::PairMode::Conservative;
  CHECK(collide(cube, pin, request, result));
}
