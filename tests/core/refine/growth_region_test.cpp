// The two margins the adaptive mode's guarantees rest on, as values: the conservative growth
// across the view (half a pixel plus the 2/256 pixel that covers the vertex stage's snapping,
// docs/algorithm.md "The conservative mode"), and the region a finer frame looks at (the
// conservative contact box and both blocks' boxes grown by twice that growth, "Adaptive
// refinement" step 5), read where the mode reports it: an apart_at_limit pair's unresolved box.

#include <catch2/catch.hpp>
#include <utility>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/refine/adaptive.hpp"

using namespace recode;
using Eigen::Vector3d;

namespace {

core::Aabb grownBy(core::Aabb box, const Vector3d& by) {
  box.min -= by;
  box.max += by;
  return box;
}

core::Aabb common(const core::Aabb& a, const core::Aabb& b) {
  core::Aabb r;
  r.min = a.min.cwiseMax(b.min);
  r.max = a.max.cwiseMin(b.max);
  return r;
}

// Seen along z over [-1, 1] x [-2, 2] at 16 x 16: pixels 0.125 wide and 0.25 high.
core::PairRequest frame16() {
  core::PairRequest r;
  r.frame.axis = core::ViewAxis::Z;
  r.frame.window = {-1, -2, 1, 2};
  r.frame.width = 16;
  r.frame.height = 16;
  r.mor = core::MorMode::Min;
  r.contact = true;
  return r;
}

}  // namespace

TEST_CASE("the conservative growth across the view is half a pixel and 2/256 of one") {
  const core::PairRequest request = frame16();
  core::Aabb a;
  a.min = Vector3d(-0.5, -0.5, -0.25);
  a.max = Vector3d(0.5, 0.5, 0.25);
  const Vector3d g = core::conservativeGrowth(request.frame, a, a);
  // Half a pixel would leave no room for the snapping to 1/256 pixel: the grown square must
  // hold a pixel centre's whole +-1/256 pixel square.
  CHECK(g.x() == Approx((0.5 + 2.0 / 256.0) * 0.125).epsilon(1e-15));
  CHECK(g.y() == Approx((0.5 + 2.0 / 256.0) * 0.25).epsilon(1e-15));
  CHECK(g.x() > 0.5 * 0.125 + 1.0 / 256.0 * 0.125);
  // Along the view: four steps of the grown pair's range, e = 4 r / (N - 8).
  const double n = static_cast<double>(raster::kDepthMax);
  CHECK(g.z() == Approx(4.0 * 0.5 / (n - 8.0)).epsilon(1e-12));
}

TEST_CASE("the conservative growth takes the frame's axes: u and v across and d along the view") {
  // The image plane's (u, v, d) are world (y, z, x) seen along x and (z, x, y) seen along y
  // (OrthoView::toPlane). Pixels 0.125 along u and 0.25 along v; the box spans 1, 2 and 4
  // along x, y and z, so each depth growth, 4 r / (N - 8), names the axis it was taken along.
  core::FrameSpec frame = frame16().frame;
  core::Aabb a;
  a.min = Vector3d(-0.5, -1, -2);
  a.max = Vector3d(0.5, 1, 2);
  const double across = 0.5 + 2.0 / 256.0;
  const double n = static_cast<double>(raster::kDepthMax);
  frame.axis = core::ViewAxis::X;
  const Vector3d gx = core::conservativeGrowth(frame, a, a);
  CHECK(gx.x() == Approx(4.0 * 1.0 / (n - 8.0)).epsilon(1e-12));
  CHECK(gx.y() == Approx(across * 0.125).epsilon(1e-15));
  CHECK(gx.z() == Approx(across * 0.25).epsilon(1e-15));
  frame.axis = core::ViewAxis::Y;
  const Vector3d gy = core::conservativeGrowth(frame, a, a);
  CHECK(gy.x() == Approx(across * 0.25).epsilon(1e-15));
  CHECK(gy.y() == Approx(4.0 * 2.0 / (n - 8.0)).epsilon(1e-12));
  CHECK(gy.z() == Approx(across * 0.125).epsilon(1e-15));
}

TEST_CASE("a depth range below the coordinates' rounding is grown by 1e-13 of their magnitude") {
  // 1e-12 along z at z = -1000: four of its steps are 2.4e-19, far below the ulps of 1000
  // (1.1e-13); the growth is the floor instead, 1e-13 times the largest |z|.
  const core::PairRequest request = frame16();
  core::Aabb a;
  a.min = Vector3d(-0.5, -0.5, -1000);
  a.max = Vector3d(0.5, 0.5, -1000 + 1e-12);
  const Vector3d g = core::conservativeGrowth(request.frame, a, a);
  CHECK(g.z() == Approx(1e-13 * 1000.0).epsilon(1e-12));
}

TEST_CASE("an unresolved region is the conservative contact grown by two growths") {
  // Two cubes turned 45 degrees about z touching on the face x + y = 0, which stands along the
  // view: the reference run sees nothing, the conservative one a band along the face, and with
  // no refinement allowed the region is reported as it was computed.
  const Vector3d n = Vector3d(1, 1, 0).normalized();
  const Eigen::AngleAxisd turn(0.25 * 3.14159265358979323846, Vector3d::UnitZ());
  const core::TriangleMesh cube = core::makeBox(0.6, 0.6, 0.3);
  const core::TriangleMesh a =
      core::transformed(cube, Eigen::Affine3d(Eigen::Translation3d(-0.6 * n) * turn));
  const core::TriangleMesh b =
      core::transformed(cube, Eigen::Affine3d(Eigen::Translation3d(0.6 * n) * turn));
  const core::PairRequest request = frame16();
  raster::CpuDevice device(16, 16);
  core::RefineLimits limits;
  limits.maxLevel = 0;
  core::AdaptivePairTester tester(limits);
  const core::AdaptiveResult out = tester.collide(device, a, b, request);
  REQUIRE(out.verdict == core::PairVerdict::ApartAtLimit);

  const core::ConservativeResult wide = core::collideConservative(device, a, b, request);
  REQUIRE(wide.pair.collide);
  const Vector3d margin = 2.0 * wide.growth;
  const core::Aabb expected =
      common(grownBy(wide.pair.contact.box, margin),
             common(grownBy(core::boundingBox(a), margin), grownBy(core::boundingBox(b), margin)));
  for (int d = 0; d < 3; ++d) {
    CAPTURE(d);
    CHECK(out.unresolved.min[d] == Approx(expected.min[d]).margin(1e-12));
    CHECK(out.unresolved.max[d] == Approx(expected.max[d]).margin(1e-12));
  }
  // That is the common part of the contact box and both blocks' boxes with two growths beyond
  // it on each side across the view, not one.
  const core::Aabb tight =
      common(wide.pair.contact.box, common(core::boundingBox(a), core::boundingBox(b)));
  for (int d = 0; d < 2; ++d) {
    CAPTURE(d);
    CHECK(out.unresolved.max[d] - out.unresolved.min[d] ==
          Approx(tight.max[d] - tight.min[d] + 4.0 * wide.growth[d]).margin(1e-12));
  }
}
