// The contact region's arithmetic at one pixel, on depths set by hand (concludeContact, the
// stage collidePair runs after the passes): where a pixel's point lies across the view (the
// pixel centre) and what a collapsed pixel's single depth is (the midpoint of its two ends,
// rounded half up). Each is a value a renderer-level test sees only through a whole scene.

#include <catch2/catch.hpp>
#include <cstdint>

#include "pair_stages.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/raster/pixel_summary.hpp"
#include "recode/raster/state.hpp"

using namespace recode;

namespace {

// Seen along z over [0, 4] x [0, 8] at 4 x 4: pixels 1 wide and 2 high. The depth range is
// [0, kDepthMax], so depth step s lies at z = kDepthMax - s.
constexpr double kRange = static_cast<double>(raster::kDepthMax);

core::OrthoView view4x4() {
  return core::OrthoView(core::ViewAxis::Z, core::ViewWindow{0, 0, 4, 8}, 4, 4, 0.0, kRange);
}

// The result of one pair whose only interfering pixel is (x, y), with the contact pass's near
// and far depths there, after concludeContact.
core::PairResult measureOnePixel(int x, int y, std::uint32_t nearEnd, std::uint32_t farEnd,
                                 bool normal = false) {
  const raster::PixelRect frame{0, 0, 4, 4};
  core::PairResult r;
  r.depthMin = 0.0;
  r.depthMax = kRange;
  r.caseMap = raster::PixelBuffer<std::uint8_t>(frame, 0);
  r.caseMap.at(x, y) = 5;  // interfering: A's interval holds B's
  r.interferingPixels = 1;
  r.contactRect = raster::PixelRect{x, y, x + 1, y + 1};
  raster::PixelBuffer<std::uint32_t> nearDepth(frame, 0), farDepth(frame, 0);
  nearDepth.at(x, y) = nearEnd;
  farDepth.at(x, y) = farEnd;
  const core::TriangleMesh box = core::makeBox(0.5, 0.5, 0.5);
  const core::PairBlock block(box);
  core::PairRequest request;
  request.frame.axis = core::ViewAxis::Z;
  request.frame.window = {0, 0, 4, 8};
  request.frame.width = 4;
  request.frame.height = 4;
  request.normal = normal;
  core::detail::concludeContact(nearDepth, farDepth, view4x4(), block, block, request, r);
  return r;
}

}  // namespace

TEST_CASE("a contact point lies at its pixel's centre across the view") {
  const core::PairResult r = measureOnePixel(2, 1, 100, 200);
  REQUIRE(r.contact.points.size() == 1);
  // Pixel (2, 1) spans u in [2, 3] and v in [2, 4]: its centre is (2.5, 3), not a corner.
  CHECK(r.contact.points[0].x() == 2.5);
  CHECK(r.contact.points[0].y() == 3.0);
  // The box spans the pixel's two ends at that centre, nothing across.
  CHECK(r.contact.box.min.x() == 2.5);
  CHECK(r.contact.box.max.x() == 2.5);
  CHECK(r.contact.box.min.y() == 3.0);
  CHECK(r.contact.box.max.y() == 3.0);
  CHECK(r.contact.box.min.z() == Approx(kRange - 200).epsilon(0).margin(1e-3));
  CHECK(r.contact.box.max.z() == Approx(kRange - 100).epsilon(0).margin(1e-3));
  CHECK(r.contact.collapsedPixels == 0);
}

TEST_CASE("a collapsed pixel's depth is the midpoint of its ends, rounded half up") {
  // The near end past the far end by rounding: the overlap is the single depth between them.
  struct Ends {
    std::uint32_t nearEnd, farEnd, midpoint;
  };
  const Ends cases[] = {
      {5, 3, 4},  // both odd: the halves 2 and 1 lose a half each, the rounding term adds it back
      {6, 4, 5},  // both even: nothing lost
      {6, 3, 4},  // one odd: 4.5 is floor(6/2) + floor(3/2) = 4
      {raster::kDepthMax, raster::kDepthMax - 2, raster::kDepthMax - 1},  // at the far end
  };
  for (const Ends& e : cases) {
    CAPTURE(e.nearEnd, e.farEnd);
    const core::PairResult r = measureOnePixel(1, 2, e.nearEnd, e.farEnd);
    REQUIRE(r.contact.points.size() == 1);
    CHECK(r.contact.collapsedPixels == 1);
    CHECK(r.contact.maxDepth == 0.0);
    const double z = kRange - static_cast<double>(e.midpoint);
    CHECK(r.contact.points[0].z() == Approx(z).epsilon(0).margin(1e-3));
    CHECK(r.contact.box.min.z() == Approx(z).epsilon(0).margin(1e-3));
    CHECK(r.contact.box.max.z() == Approx(z).epsilon(0).margin(1e-3));
  }
}

TEST_CASE("a pixel whose two ends meet at one depth is not collapsed") {
  // Near end == far end: a zero-length interval, not a near end past the far one.
  const core::PairResult r = measureOnePixel(1, 2, 150, 150);
  REQUIRE(r.contact.points.size() == 1);
  CHECK(r.contact.collapsedPixels == 0);
  CHECK(r.contact.maxDepth == 0.0);
  CHECK(r.contact.points[0].z() == Approx(kRange - 150).epsilon(0).margin(1e-3));
}

TEST_CASE("an overlap with no thickness along the view has no depth along its normal") {
  // One pixel whose ends meet: both samples are the same point, so the overlap's width is the
  // pixel square's extent alone, which along the view axis (the normal found) is nothing.
  const core::PairResult r = measureOnePixel(1, 2, 150, 150, true);
  REQUIRE(r.contact.normal);
  CHECK(r.contact.normal->normal.cwiseAbs() == Eigen::Vector3d::UnitZ());
  CHECK(r.contact.normal->depth == 0.0);
}

TEST_CASE("the contact box from a summary starts at the first pixel's centre") {
  // concludeSummaryContact over a contact rectangle at the frame's corner: its first column's
  // and row's centres are u = 0.5 / 4 * 4 and v = 0.5 / 4 * 8 exactly (powers of two), as
  // concludeContact puts them; its last are (1.5, 3).
  core::PairResult r;
  r.depthMin = 0.0;
  r.depthMax = kRange;
  r.contactRect = raster::PixelRect{0, 0, 2, 2};
  raster::DepthIntervals d;
  d.nearest = 100;
  d.farthest = 200;
  d.longest = 100;
  core::detail::concludeSummaryContact(d, view4x4(), r);
  CHECK(r.contact.box.min.x() == 0.5);
  CHECK(r.contact.box.min.y() == 1.0);
  CHECK(r.contact.box.max.x() == 1.5);
  CHECK(r.contact.box.max.y() == 3.0);
  CHECK(r.contact.box.min.z() == Approx(kRange - 200).epsilon(0).margin(1e-3));
  CHECK(r.contact.box.max.z() == Approx(kRange - 100).epsilon(0).margin(1e-3));
}
