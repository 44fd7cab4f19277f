// The contact normal and penetration depth (contact_normal.hpp): known answers on blocks placed
// so that the exact overlap is known (boxes face to face seen along and across the contact
// normal, a sphere pressed into a box face), the sign under swapping the blocks, and the
// default request leaving the result as it was.

#include <Eigen/Geometry>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "pair_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/pair/contact_normal.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"

using namespace recode;
using Eigen::Vector3d;
using test::boxBetween;
using test::frameZ;

namespace {

core::PairResult runWithNormal(const core::TriangleMesh& a, const core::TriangleMesh& b,
                               const core::FrameSpec& frame) {
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  request.normal = true;
  return core::collidePair(device, a, b, request);
}

double degreesBetween(const Vector3d& u, const Vector3d& v) {
  return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

// One depth step of a pair whose depth range is `range` world units long.
double depthStep(double range) {
  return range / 16777215.0;
}

}  // namespace

TEST_CASE("boxes face to face along the view axis: the face normal, the overlap's thickness") {
  // Overlap [0.5, 1.5]^2 x [0.8, 1]; pixels of 1/16 put the overlap's sides on pixel edges.
  const core::TriangleMesh a = boxBetween({0, 0, 0}, {2, 2, 1});
  const core::TriangleMesh b = boxBetween({0.5, 0.5, 0.8}, {1.5, 1.5, 2});
  const core::PairResult r = runWithNormal(a, b, frameZ(0, 0, 2, 2, 32, 32));
  REQUIRE(r.contact.normal);
  CHECK(r.contact.normal->normal == Vector3d(0, 0, 1));  // B lies above A
  CHECK(std::abs(r.contact.normal->depth - 0.2) <= 2 * depthStep(2.0));
}

TEST_CASE("boxes face to face across the view axis: the invisible faces' normal, exactly") {
  // Overlap [0.75, 1] x [0, 1] x [0, 1]: the faces in contact are parallel to the view axis, so
  // no depth surface shows them; the overlap is thinnest along x all the same.
  const core::TriangleMesh a = boxBetween({0, 0, 0}, {1, 1, 1});
  const core::TriangleMesh b = boxBetween({0.75, -0.5, -0.5}, {2, 1.5, 1.5});
  const core::PairResult r = runWithNormal(a, b, frameZ(-0.5, -0.5, 2, 2, 40, 40));
  REQUIRE(r.contact.normal);
  CHECK(r.contact.normal->normal == Vector3d(1, 0, 0));
  CHECK(r.contact.normal->depth == Approx(0.25).margin(1e-12));
}

TEST_CASE("a sphere pressed into a box face: the face normal, the cap's height") {
  // The sphere's lowest point (a pole of the mesh) lies 0.1 below the box's top face z = 1; the
  // overlap is a cap 0.1 high and about 0.44 across, thinnest along z, seen along z and from
  // the side (along x, where the normal lies in the image plane).
  const core::TriangleMesh box = boxBetween({-2, -2, -1}, {2, 2, 1});
  const core::TriangleMesh sphere = test::moved(core::makeSphere(1.0, 48, 24), {0.3, -0.2, 1.9});
  for (const core::ViewAxis axis : {core::ViewAxis::Z, core::ViewAxis::X}) {
    core::FrameSpec frame = frameZ(-1, -1, 1.5, 1.5, 128, 128);
    frame.axis = axis;
    if (axis == core::ViewAxis::X)  // (u, v) = (y, z)
      frame.window = {-1.0, 0.0, 1.0, 2.0};
    const core::PairResult r = runWithNormal(box, sphere, frame);
    REQUIRE(r.contact.normal);
    CHECK(degreesBetween(r.contact.normal->normal, Vector3d(0, 0, 1)) < 1.0);
    CHECK(r.contact.normal->depth == Approx(0.1).margin(0.02));
  }
}

TEST_CASE("swapping A and B turns the normal round and keeps the depth") {
  const core::TriangleMesh a = boxBetween({0, 0, 0}, {1, 1, 1});
  const core::TriangleMesh b = test::moved(core::makeSphere(0.5, 32, 16), {1.3, 0.5, 0.5});
  const core::FrameSpec frame = frameZ(-0.5, -0.5, 2, 2, 64, 64);
  const core::PairResult ab = runWithNormal(a, b, frame);
  const core::PairResult ba = runWithNormal(b, a, frame);
  REQUIRE(ab.contact.normal);
  REQUIRE(ba.contact.normal);
  CHECK(degreesBetween(ab.contact.normal->normal, Vector3d(1, 0, 0)) < 2.0);  // A towards B
  CHECK(degreesBetween(ab.contact.normal->normal, -ba.contact.normal->normal) < 1e-6);
  CHECK(ab.contact.normal->depth == Approx(ba.contact.normal->depth).epsilon(1e-9));
}

TEST_CASE("without the request there is no normal, and with it nothing else changes") {
  const core::TriangleMesh a = boxBetween({0, 0, 0}, {1, 1, 1});
  const core::TriangleMesh b = test::moved(core::makeSphere(0.5, 32, 16), {1.3, 0.5, 0.7});
  const core::FrameSpec frame = frameZ(-0.5, -0.5, 2, 2, 64, 64);
  const core::PairResult plain = test::runPair(a, b, frame);
  const core::PairResult with = runWithNormal(a, b, frame);
  CHECK_FALSE(plain.contact.normal);
  REQUIRE(with.contact.normal);
  CHECK(with.contact.points == plain.contact.points);
  CHECK(with.contact.maxDepth == plain.contact.maxDepth);
  CHECK(with.caseCounts == plain.caseCounts);
  // Apart: no normal even when asked.
  const core::PairResult apart = runWithNormal(a, test::moved(b, {2, 0, 0}), frame);
  CHECK_FALSE(apart.collide);
  CHECK_FALSE(apart.contact.normal);
}

TEST_CASE("overlapWidth: the spread of the ends plus a pixel's extent along the direction") {
  const Vector3d ends[] = {{0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {2, 0, 1}};
  const core::OverlapSamples s{ends, Vector3d(0.5, 0.25, 0)};
  CHECK(core::overlapWidth(s, Vector3d(1, 0, 0)) == 3.0);
  CHECK(core::overlapWidth(s, Vector3d(0, 1, 0)) == 0.5);
  CHECK(core::overlapWidth(s, Vector3d(0, 0, 1)) == 1.0);
  CHECK(core::thinnestDirection(s).cwiseAbs().isApprox(Vector3d(0, 1, 0)));
}
