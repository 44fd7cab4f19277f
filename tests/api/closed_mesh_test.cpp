// Closed meshes in the collision API: made and validated, collided by the layered pair against a
// convex block or another closed mesh, with oracles from geometry (a peg through a torus's hole
// or through its tube, a ball in a hollow box's cavity or in its wall, lens and box volumes
// against their formulas), and the API's answer equal to core::collideLayered's in the same
// frame. What the layered pair cannot answer is refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "recode/api/collision.hpp"
#include "recode/api/manager.hpp"
#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"
#include "test_shapes.hpp"

namespace {

using namespace recode;
using Catch::Matchers::Contains;

constexpr double kTorusRadius = 2.0, kTubeRadius = 0.5;

CollisionGeometryPtr closedShape(core::TriangleMesh mesh, const char* name) {
  return CollisionGeometry::closed(ClosedMesh::fromMesh(std::move(mesh), name));
}
CollisionGeometryPtr convexShape(core::TriangleMesh mesh, const char* name) {
  return CollisionGeometry::single(ConvexBlock::fromMesh(std::move(mesh), name));
}
CollisionGeometryPtr torus() {
  return closedShape(core::makeTorus(kTorusRadius, kTubeRadius, 96, 48), "torus");
}
Eigen::Isometry3d at(const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}
// A peg along z of `radius`, from z = -2 to 2, its axis through (x, 0).
CollisionObject peg(double radius, double x) {
  return CollisionObject(convexShape(core::makeCylinder(radius, 4.0, 64), "peg"),
                         at({x, 0.0, -2.0}));
}
CollisionResult collided(const CollisionObject& a, const CollisionObject& b,
                         const CollisionRequest& request = {}) {
  CollisionResult result;
  collide(a, b, request, result);
  return result;
}

}  // namespace

TEST_CASE("a closed mesh is validated when made, with the closed-mesh check's message") {
  const auto made = ClosedMesh::fromMesh(core::makeTorus(2.0, 0.5, 16, 8), "ring");
  CHECK(made->name() == "ring");
  const auto g = CollisionGeometry::closed(made);
  CHECK(g->isClosed());
  CHECK(g->closedMesh() == made);
  CHECK(g->blockCount() == 1);
  CHECK(g->name() == "ring");
  CHECK_THROWS_WITH(g->part(0), Contains("closed mesh, not convex blocks"));
  CHECK_FALSE(convexShape(core::makeBox(1, 1, 1), "box")->isClosed());

  core::TriangleMesh open = core::makeTorus(2.0, 0.5, 16, 8);
  open.triangles.pop_back();
  std::string expected;
  try {
    core::validateClosedMesh(open, "ring");
  } catch (const core::MeshError& e) {
    expected = e.what();
  }
  REQUIRE_THAT(expected, Contains("ring: "));
  CHECK_THROWS_WITH(ClosedMesh::fromMesh(open, "ring"), expected);
  CHECK_THROWS_WITH(ClosedMesh::fromArrays(open.vertices, open.triangles, "ring"), expected);
  CHECK_THROWS_AS(ClosedMesh::fromFile("no/such/file.obj"), core::MeshError);
  CHECK_THROWS_AS(CollisionGeometry::closed(nullptr), std::invalid_argument);
  // A torus is no convex block.
  CHECK_THROWS_WITH(ConvexBlock::fromMesh(core::makeTorus(2.0, 0.5, 16, 8), "ring"),
                    Contains("ring: Euler characteristic"));
}

TEST_CASE("a peg through a torus's hole does not interfere; one through its tube does") {
  const CollisionObject ring(torus());
  // The hole's radius is 1.5 (less a hair for the tessellation): a peg of 0.5 is far from it.
  const CollisionResult hole = collided(ring, peg(0.5, 0.0));
  CHECK_FALSE(hole.collide);
  REQUIRE(hole.layered);
  CHECK(hole.layered->result.overlapVolume == 0.0);
  CHECK(hole.layered->result.containment == core::Containment::None);
  // Seen along z over the peg (the overlap box is a cube: ties go to z), the hole holds no
  // torus: no layer of it at any MOR pixel, one of the peg.
  CHECK(hole.layered->frame.axis == core::ViewAxis::Z);
  CHECK(hole.layered->result.layersA == 0);
  CHECK(hole.layered->result.layersB == 1);
  CHECK(hole.contacts.empty());

  CollisionRequest alongX;
  alongX.axis = AxisChoice::X;
  const CollisionResult tube = collided(ring, peg(0.2, kTorusRadius), alongX);
  CHECK(tube.collide);
  REQUIRE(tube.layered);
  const core::LayeredPairResult& r = tube.layered->result;
  CHECK(r.collide);
  // A line along x at one height crosses the torus's section there, an annulus, twice at most,
  // and twice through the tube's middle.
  CHECK(tube.layered->frame.axis == core::ViewAxis::X);
  CHECK(r.layersA == 2);
  CHECK(r.layersB == 1);
  CHECK(r.containment == core::Containment::None);
  CHECK(r.passes == 4 + 2 * (r.layersA + r.layersB));
  REQUIRE(tube.contacts.size() == 1);
  CHECK(tube.contacts[0].layered);
  CHECK(tube.contacts[0].pair.interferingPixels == tube.interferingPixels);
  CHECK(tube.interferingPixels == r.interferingPixels);
  // Every contact point lies inside the tube and inside the peg (within a pixel's reach).
  REQUIRE_FALSE(tube.contact.points.empty());
  const core::FrameSpec& f = tube.layered->frame;
  const double pixel = (f.window.umax - f.window.umin) / f.width;
  for (const Eigen::Vector3d& p : tube.contact.points) {
    const double rho = std::hypot(p.x(), p.y());
    CHECK(std::hypot(rho - kTorusRadius, p.z()) <= kTubeRadius + pixel);
    CHECK(std::hypot(p.x() - kTorusRadius, p.y()) <= 0.2 + pixel);
  }
  // The overlap's volume: the tube's chord 2 sqrt(r^2 - (rho - R)^2) over the peg's disc, by a
  // fine midpoint sum. Within 3 %: the tessellations (96 x 48 torus, 64-gon peg) lose under 1 %,
  // the pixels (256 across the overlap box) about 2 %.
  double exact = 0.0;
  const int n = 800;
  const double h = 0.4 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = kTorusRadius - 0.2 + (i + 0.5) * h, y = -0.2 + (j + 0.5) * h;
      if (std::hypot(x - kTorusRadius, y) > 0.2)
        continue;
      const double d = std::hypot(x, y) - kTorusRadius;
      exact += 2.0 * std::sqrt(std::max(0.0, kTubeRadius * kTubeRadius - d * d)) * h * h;
    }
  CHECK(r.overlapVolume == Approx(exact).epsilon(0.03));
}

TEST_CASE("a ball in a hollow box's cavity is apart; one in its wall is contained") {
  using core::test::joined;
  using core::test::reversed;
  // A box of half side 2 with a cavity of half side 1.5: walls 0.5 thick.
  const CollisionObject hollow(closedShape(
      joined(core::makeBox(2, 2, 2), reversed(core::makeBox(1.5, 1.5, 1.5))), "hollow box"));
  const auto ball = [](double radius, double x) {
    return CollisionObject(convexShape(core::makeSphere(radius, 32, 16), "ball"), at({x, 0, 0}));
  };
  const CollisionResult cavity = collided(ball(1.0, 0.0), hollow);
  CHECK_FALSE(cavity.collide);
  REQUIRE(cavity.layered);
  CHECK(cavity.layered->result.containment == core::Containment::None);
  CHECK(cavity.layered->result.layersB == 2);  // the outer wall and the cavity's wall

  const CollisionResult wall = collided(ball(0.2, 1.75), hollow);
  CHECK(wall.collide);
  CHECK(wall.layered->result.containment == core::Containment::AInsideB);
  CHECK(collided(hollow, ball(0.2, 1.75)).layered->result.containment ==
        core::Containment::BInsideA);

  // A ball across the cavity's wall: interferes, contained in neither.
  const CollisionResult across = collided(ball(0.4, 1.5), hollow);
  CHECK(across.collide);
  CHECK(across.layered->result.containment == core::Containment::None);
}

TEST_CASE("a ball inside a torus's tube is contained, whichever side is the closed mesh") {
  const CollisionObject ring(torus());
  const core::TriangleMesh sphere = core::makeSphere(0.3, 32, 16);
  const CollisionObject ball(closedShape(sphere, "ball"), at({0.0, kTorusRadius, 0.0}));
  const CollisionResult r = collided(ball, ring);
  CHECK(r.collide);
  CHECK(r.layered->result.containment == core::Containment::AInsideB);
  CHECK(collided(ring, ball).layered->result.containment == core::Containment::BInsideA);
  // The overlap is the ball's mesh: its volume (exact for the polyhedron) within 2 %, about a
  // pixel's width along the rim of its projection (256 pixels across 0.6).
  CHECK(r.layered->result.overlapVolume == Approx(core::signedVolume(sphere)).epsilon(0.02));
}

TEST_CASE("overlap volumes of two balls and of two boxes match their formulas") {
  // Two unit balls, centres 1 apart: the lens has volume pi (4r + d)(2r - d)^2 / 12. Within 2 %:
  // the 96 x 48 tessellation loses about 0.5 % near the rim, the pixels about 1 %.
  const CollisionObject a(closedShape(core::makeSphere(1.0, 96, 48), "ball a"));
  const CollisionObject b(convexShape(core::makeSphere(1.0, 96, 48), "ball b"), at({1, 0, 0}));
  const double lens = std::numbers::pi * 5.0 * 1.0 / 12.0;
  CHECK(collided(a, b).layered->result.overlapVolume == Approx(lens).epsilon(0.02));

  // Boxes of half side 1, offset (0.5, 0.3, 0.2): the overlap is 1.5 x 1.7 x 1.8. The pixel
  // centres inside a w x h rectangle miss at most a pixel p along each side: relative error
  // p (1/w + 1/h) + p^2/(w h), under 1 % at 256 pixels across.
  const CollisionObject boxA(closedShape(core::makeBox(1, 1, 1), "box a"));
  const CollisionObject boxB(convexShape(core::makeBox(1, 1, 1), "box b"), at({0.5, 0.3, 0.2}));
  const CollisionResult boxes = collided(boxA, boxB);
  CHECK(boxes.layered->result.overlapVolume == Approx(1.5 * 1.7 * 1.8).epsilon(0.01));
  CHECK(boxes.layered->result.containment == core::Containment::None);
  // A box inside the other: contained, its own volume.
  const CollisionObject small(closedShape(core::makeBox(0.5, 0.25, 0.4), "small"),
                              at({0.2, 0.1, 0.0}));
  const CollisionResult inside = collided(boxB, small);  // boxB at (0.5, 0.3, 0.2) holds it
  CHECK(inside.layered->result.containment == core::Containment::BInsideA);
  CHECK(inside.layered->result.overlapVolume == Approx(1.0 * 0.5 * 0.8).epsilon(0.01));
}

TEST_CASE("the API's layered answer is core::collideLayered's in the same frame") {
  Eigen::Isometry3d pose = at({0.3, kTorusRadius - 0.1, -0.2});
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const CollisionObject ring(torus(), at({0.1, 0.0, 0.05}));
  const CollisionObject stick(convexShape(core::makeCylinder(0.3, 1.5, 24), "stick"), pose);
  CollisionRequest request;
  request.resolution = 96;
  request.normal = true;
  const CollisionResult api = collided(ring, stick, request);
  REQUIRE(api.collide);

  core::PairRequest pair;
  pair.frame = chooseFrame(ring.worldBox(), stick.worldBox(), request);
  pair.normal = true;
  raster::CpuDevice device(pair.frame.width, pair.frame.height);
  const core::LayeredPairResult core =
      core::collideLayered(device, ring.worldBlock(0), stick.worldBlock(0), pair);
  const core::LayeredPairResult& r = api.layered->result;
  CHECK(api.layered->frame.width == pair.frame.width);
  CHECK(api.layered->frame.height == pair.frame.height);
  CHECK(r.collide == core.collide);
  CHECK(r.interferingPixels == core.interferingPixels);
  CHECK(r.mor == core.mor);
  CHECK(r.overlapVolume == core.overlapVolume);
  CHECK(r.containment == core.containment);
  CHECK(r.layersA == core.layersA);
  CHECK(r.layersB == core.layersB);
  CHECK(r.passes == core.passes);
  CHECK(r.overlapSteps.data == core.overlapSteps.data);
  CHECK(r.contact.points == core.contact.points);
  CHECK(r.contact.maxDepth == core.contact.maxDepth);
  REQUIRE(r.contact.normal);
  CHECK(r.contact.normal->normal == core.contact.normal->normal);
  CHECK(api.contact.points == core.contact.points);
  CHECK(api.interferingPixels == core.interferingPixels);
}

TEST_CASE("on two convex blocks the layered pair interferes where RECODE's passes do") {
  // The same cones, one as a closed mesh: the same frame and the same interfering pixels.
  Eigen::Isometry3d upper = at({0.2, 0.1, 1.9});
  upper.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
  const core::TriangleMesh cone = core::makeCone(1.0, 2.0, 32);
  const CollisionObject convexA(convexShape(cone, "cone")),
      convexB(convexShape(cone, "cone"), upper);
  const CollisionObject closedA(closedShape(cone, "cone"));
  const CollisionResult passes = collided(convexA, convexB);
  const CollisionResult layers = collided(closedA, convexB);
  REQUIRE(passes.collide);
  CHECK_FALSE(passes.layered);
  REQUIRE(layers.layered);
  CHECK(layers.collide);
  // Convex blocks have one layer each at every pixel: 4 count passes and 2 capture passes each.
  CHECK(layers.layered->result.layersA == 1);
  CHECK(layers.layered->result.layersB == 1);
  CHECK(layers.layered->result.passes == 8);
  CHECK(layers.interferingPixels == passes.interferingPixels);
  CHECK(layers.contacts[0].frame.width == passes.contacts[0].frame.width);
}

TEST_CASE("what the layered pair cannot answer is refused, naming the objects and the rule") {
  const CollisionObject ring(torus());
  CollisionRequest adaptive;
  adaptive.mode = core::PairMode::Adaptive;
  CollisionResult result;
  CHECK_THROWS_WITH(collide(ring, peg(0.2, 2.0), adaptive, result),
                    Contains("mode adaptive applies to pairs of convex blocks") &&
                        Contains("closed mesh 'torus'") && Contains("reference mode only"));
  const auto cube = ConvexBlock::fromMesh(core::makeBox(0.2, 0.2, 0.2), "cube");
  const CollisionObject pair(CollisionGeometry::compound(
      {{cube, Eigen::Isometry3d::Identity()}, {cube, at({0.5, 0, 0})}}, "two cubes"));
  CHECK_THROWS_WITH(collide(pair, ring, {}, result), Contains("compound 'two cubes' of 2 blocks") &&
                                                         Contains("one solid on each side"));
}

TEST_CASE("the manager decides pairs with a closed mesh by layers") {
  CollisionManager manager;
  const ObjectId ring = manager.add(std::make_shared<CollisionObject>(torus()));
  const ObjectId tube = manager.add(std::make_shared<CollisionObject>(peg(0.2, kTorusRadius)));
  manager.add(std::make_shared<CollisionObject>(peg(0.5, 0.0)));  // through the hole
  const std::vector<ObjectContact> contacts = manager.collide(CollisionRequest{});
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].a == ring);
  CHECK(contacts[0].b == tube);
  REQUIRE(contacts[0].result.layered);
  CHECK(contacts[0].result.layered->result.overlapVolume > 0.0);
  CHECK(contacts[0].result.layered->result.overlapVolume ==
        collided(CollisionObject(torus()), peg(0.2, kTorusRadius)).layered->result.overlapVolume);
}
