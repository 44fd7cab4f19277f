// The contact normal and penetration depth (contact_normal.hpp): known answers on blocks placed
// so that the exact overlap is known (boxes face to face seen along and across the contact
// normal, a sphere pressed into a box face), the sign under swapping the blocks, and the
// default request leaving the result as it was; and on samples made by hand: the row hulls the
// search reduces the ends to (down to subnormal cross products), a seed of the direction spiral
// coming back exactly, and the sign of blocks far from the origin.

#include <Eigen/Geometry>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

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

namespace {

double degreesBetweenLines(const Vector3d& u, const Vector3d& v) {
  return std::acos(std::min(1.0, std::abs(u.normalized().dot(v.normalized())))) * 180.0 /
         std::numbers::pi;
}

// The ends of a hand-made overlap given as lattice points, each coordinate times `unit`.
std::vector<Vector3d> scaled(std::vector<Vector3d> ends, double unit) {
  for (Vector3d& p : ends)
    p *= unit;
  return ends;
}

}  // namespace

TEST_CASE(
    "thinnestDirection: a box overlap away from the origin is thinnest across its thin side") {
  // A 16 x 16 pixel view along z of the overlap [5, 6] x [0, 1] x [0, 0.5], pixel after pixel,
  // row (equal y) after row: 16 rows of 32 ends, so the search keeps each row's hull corners in
  // (z, x), the four ends at x = 5 + 1/32 and 6 - 1/32. The box is thinnest along z (0.5, and
  // no pixel term along z); a hull that lost the far corner at low x would see a wedge, thinner
  // across its slanted side. Its x offset from z is what a hull mixing up the coordinates of
  // its orientation test gets wrong.
  const int n = 16;
  const double h = 0.5 / n;
  std::vector<Vector3d> ends;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j) {
      const double x = 5.0 + (j + 0.5) / n, y = (k + 0.5) / n;
      ends.push_back({x, y, 0.0});
      ends.push_back({x, y, 0.5});
    }
  const Vector3d d = core::thinnestDirection(core::OverlapSamples{ends, Vector3d(h, h, 0)});
  CHECK(degreesBetweenLines(d, Vector3d::UnitZ()) < 0.01);
}

TEST_CASE("thinnestDirection: rows of a lattice parallelogram at a subnormal scale") {
  // Each row (equal y, y = 0..3) holds the parallelogram (z, x) = (0,0), (1,0), (1,1), (2,1):
  // edges along z (1 apart along x) and along (1, 1) (1/sqrt 2 apart), so with small pixels the
  // ends are thinnest along (x, z) ~ (-1, 1), across the slanted edges. Without the corners
  // (1,0) and (1,1) a row is the segment from (0,0) to (2,1), thinnest along (x, z) ~ (-2, 1),
  // 18.4 degrees away. Both corners turn by one lattice unit squared (the orientation test's
  // cross product is 1). The widths scale exactly with a power of two, the cross products with
  // its square, so at a lattice unit of 2^-537 that turn is the least subnormal, 2^-1074, and at
  // 2^-538 it is 2^-1076, which rounds to zero.
  const double zx[4][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 1}};
  const Vector3d halfPixel(0.125, 0.125, 0);
  const Vector3d expected(-1, 0, 1);
  SECTION("rows of 8 ends are reduced to their corners, and a turn of one subnormal is a corner") {
    std::vector<Vector3d> ends;
    for (int y = 0; y < 4; ++y)
      for (int twice = 0; twice < 2; ++twice)
        for (const auto& p : zx)
          ends.push_back({p[1], double(y), p[0]});
    const double unit = std::ldexp(1.0, -537);
    const Vector3d d =
        core::thinnestDirection(core::OverlapSamples{scaled(ends, unit), unit * halfPixel});
    CHECK(degreesBetweenLines(d, expected) < 0.01);
  }
  SECTION("rows of 4 ends are too short to reduce (4 runs of 16 ends): every end is used") {
    std::vector<Vector3d> ends;
    for (int y = 0; y < 4; ++y)
      for (const auto& p : zx)
        ends.push_back({p[1], double(y), p[0]});
    const double unit = std::ldexp(1.0, -538);
    const Vector3d d =
        core::thinnestDirection(core::OverlapSamples{scaled(ends, unit), unit * halfPixel});
    CHECK(degreesBetweenLines(d, expected) < 0.01);
  }
  SECTION("runs along the view axis (no pixel extent) are not rows: every end is used") {
    // The same parallelogram in (x, y) at z = 0..3 (layers of 8 ends): 4 runs of equal z, but
    // along z a run is not a pixel row, and x and y change too often to reduce.
    const double xy[4][2] = {{0, 0}, {1, 1}, {1, 2}, {0, 1}};
    std::vector<Vector3d> ends;
    for (int z = 0; z < 4; ++z)
      for (int twice = 0; twice < 2; ++twice)
        for (const auto& p : xy)
          ends.push_back({p[0], p[1], double(z)});
    const double unit = std::ldexp(1.0, -538);
    const Vector3d d =
        core::thinnestDirection(core::OverlapSamples{scaled(ends, unit), unit * halfPixel});
    CHECK(degreesBetweenLines(d, Vector3d(1, -1, 0)) < 0.01);
  }
  SECTION("of two image axes with short enough runs, the one with fewer runs (x) is used") {
    // y = 0: 8 ends at (x, z) = (0, 0); y = 4: the parallelogram twice, x = 0 first; y = 8: 8 ends
    // at (1, 2). Runs: 2 of equal x, 3 of equal y (both under 24 / 4). Rows of equal x hold (y, z)
    // points with y a multiple of 4 units, so their cross products are exact multiples of 2^-1074;
    // the row y = 4 would lose the corners. The widths across the slanted edges do not change
    // with a tilt towards y, so the search ends within its resolution of the plane y = 0.
    std::vector<Vector3d> ends(8, Vector3d(0, 0, 0));
    for (const double x : {0.0, 1.0})
      for (int twice = 0; twice < 2; ++twice)
        for (const auto& p : zx)
          if (p[1] == x)
            ends.push_back({p[1], 4.0, p[0]});
    ends.insert(ends.end(), 8, Vector3d(1, 8, 2));
    const double unit = std::ldexp(1.0, -538);
    const Vector3d d =
        core::thinnestDirection(core::OverlapSamples{scaled(ends, unit), unit * halfPixel});
    CHECK(degreesBetweenLines(d, expected) < 0.05);
  }
}

TEST_CASE("thinnestDirection: a slab across a direction of the spiral returns that direction") {
  // The search starts from 256 directions on a golden-angle spiral over z >= 0: direction i has
  // z = (i + 1/2) / 256, r = sqrt(1 - z^2), azimuth i * pi * (3 - sqrt 5). A slab 0.2 thick
  // across direction 255 (3.6 degrees from z) and 2 x 2 wide is thinnest exactly there, with a
  // kink: every tilt the refinement tries is wider, so the seed itself comes back.
  const int i = 255;
  const double z = (i + 0.5) / 256;
  const double r = std::sqrt(1.0 - z * z);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const Vector3d d = Vector3d(r * std::cos(golden * i), r * std::sin(golden * i), z).normalized();
  const Vector3d t1 = d.cross(Vector3d::UnitX()).normalized();
  const Vector3d t2 = d.cross(t1);
  std::vector<Vector3d> ends;  // the corners, the even ones in the plane c = -1 (no good plane fit)
  for (const int a : {-1, 1})
    for (const int b : {-1, 1})
      for (const int c : {-1, 1})
        ends.push_back(0.1 * a * d + b * t1 + c * t2);
  const Vector3d got = core::thinnestDirection(core::OverlapSamples{ends, Vector3d::Zero()});
  CHECK((got - d).norm() <= 5e-16);
}

TEST_CASE("contactNormal: the sign from the extents of blocks far from the origin") {
  // A = [10, 11] x [0, 1]^2, B = [10.75, 12] x [-0.5, 1.5]^2, seen along x: the overlap is
  // [10.75, 11] along x. Moving B along +x by max_A x - min_B x = 0.25 separates them; along -x
  // it takes max_B x - min_A x = 2. So the normal is +x and the depth 0.25. (The sums are far
  // from their differences here: max_A x + min_B x = 21.75 > 2.)
  std::vector<Vector3d> ends;
  for (const double y : {0.25, 0.75})
    for (const double zc : {0.25, 0.75}) {
      ends.push_back({10.75, y, zc});
      ends.push_back({11.0, y, zc});
    }
  std::vector<Vector3d> a, b;
  for (int c = 0; c < 8; ++c) {
    const double cx = c & 1, cy = (c >> 1) & 1, cz = c >> 2;
    a.push_back({10.0 + cx, cy, cz});
    b.push_back({10.75 + 1.25 * cx, -0.5 + 2 * cy, -0.5 + 2 * cz});
  }
  const core::ContactNormal n =
      core::contactNormal(core::OverlapSamples{ends, Vector3d(0, 0.25, 0.25)}, a, b);
  CHECK(n.normal == Vector3d(1, 0, 0));
  CHECK(n.depth == 0.25);
  // Swapped, B is pushed the other way.
  const core::ContactNormal m =
      core::contactNormal(core::OverlapSamples{ends, Vector3d(0, 0.25, 0.25)}, b, a);
  CHECK(m.normal == Vector3d(-1, 0, 0));
}
