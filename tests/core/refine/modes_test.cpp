// The adaptive and conservative modes on constructed pairs whose exact answer is known by
// construction: a needle thinner than a pixel through a box (the reference misses it), boxes a
// fraction of a pixel apart or far closer (the conservative mode reports them, the adaptive mode
// rules them out by GJK's certified gap), and faces touching where no pixel sees them
// (apart_at_limit).

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/refine/pair_mode.hpp"

using namespace recode;
using Eigen::Vector3d;

namespace {

core::TriangleMesh boxBetween(const Vector3d& lo, const Vector3d& hi) {
  const Eigen::Affine3d move(Eigen::Translation3d(0.5 * (lo + hi)));
  return core::transformed(core::makeBox(0.5 * (hi - lo)), move);
}

// Two cubes of half-side 0.6 turned 45 degrees about z, facing each other across the plane
// n.x = 0 with n = (1, ny, 0)/sqrt(2) (ny = 1 or -1), `gap` apart along n: their boxes overlap
// whatever the gap, and seen along z the gap lies across the view.
std::pair<core::TriangleMesh, core::TriangleMesh> diagonalPair(double gap, double ny = 1.0) {
  const Vector3d n = Vector3d(1, ny, 0).normalized();
  const Eigen::AngleAxisd turn(0.25 * 3.14159265358979323846, Vector3d::UnitZ());
  const core::TriangleMesh cube = core::makeBox(0.6, 0.6, 0.3);
  const Eigen::Affine3d poseA(Eigen::Translation3d(-0.6 * n) * turn);
  const Eigen::Affine3d poseB(Eigen::Translation3d((0.6 + gap) * n) * turn);
  return {core::transformed(cube, poseA), core::transformed(cube, poseB)};
}

// Seen along z over [-1, 1]^2 at 16 x 16: pixels 0.125 wide, centres at odd multiples of 1/16.
core::PairRequest frame16() {
  core::PairRequest r;
  r.frame.axis = core::ViewAxis::Z;
  r.frame.window = {-1, -1, 1, 1};
  r.frame.width = 16;
  r.frame.height = 16;
  return r;
}

struct Modes {
  bool reference = false;
  core::AdaptiveResult adaptive;
  bool conservative = false;
};

Modes runModes(const core::TriangleMesh& a, const core::TriangleMesh& b,
               const core::RefineLimits& limits = {}) {
  const core::PairRequest request = frame16();
  raster::CpuDevice device(16, 16);
  core::AdaptivePairTester tester(limits);
  Modes m;
  m.reference = core::collidePair(device, a, b, request).collide;
  m.adaptive = tester.collide(device, a, b, request);
  m.conservative = core::collideConservative(device, a, b, request).pair.collide;
  return m;
}

}  // namespace

TEST_CASE("a needle between pixel centres: the reference misses it, the other modes see it") {
  // A thin bar along z between the centres at x = 0.0625 and 0.1875, y likewise; it passes
  // through the box, so the blocks intersect.
  const auto needle = boxBetween({0.09, 0.09, -0.8}, {0.16, 0.16, 0.8});
  const auto box = boxBetween({-0.7, -0.7, -0.2}, {0.7, 0.7, 0.2});
  const Modes m = runModes(needle, box);
  CHECK_FALSE(m.reference);
  CHECK(m.adaptive.verdict == core::PairVerdict::Collide);
  CHECK(m.adaptive.deepestLevel >= 1);
  REQUIRE(m.adaptive.contact);
  CHECK(m.adaptive.contact->interferingPixels > 0);
  CHECK(m.conservative);
}

TEST_CASE("blocks a third of a pixel apart across the view: conservative extra, adaptive apart") {
  const auto [a, b] = diagonalPair(0.125 / 3);
  for (const int maxLevel : {1, 6}) {
    INFO("maxLevel " << maxLevel);
    core::RefineLimits limits;
    limits.maxLevel = maxLevel;
    const Modes m = runModes(a, b, limits);
    CHECK_FALSE(m.reference);
    CHECK(m.conservative);  // within a pixel: reported
    CHECK(m.adaptive.verdict == core::PairVerdict::Apart);
    // By GJK's certified gap, 0.042, in the request's frame: nothing finer is drawn.
    CHECK(m.adaptive.deepestLevel == 0);
    CHECK(m.adaptive.runs == 1);
  }
}

TEST_CASE("blocks two pixels apart: every mode says apart in the request's frame") {
  // The box growth reaches (0.5 + 2/256) * 0.125 * sqrt(2) = 0.09 along n from each block.
  const auto [a, b] = diagonalPair(2 * 0.125);
  const Modes m = runModes(a, b);
  CHECK_FALSE(m.reference);
  CHECK_FALSE(m.conservative);
  CHECK(m.adaptive.verdict == core::PairVerdict::Apart);
  CHECK(m.adaptive.deepestLevel == 0);
  CHECK(m.adaptive.runs == 1);
}

TEST_CASE("a gap far below any pixel is apart in the request's frame, by GJK's certified gap") {
  const auto [a, b] = diagonalPair(1e-6);  // the pixels of level 6, 0.125 / 4096, are wider
  const Modes m = runModes(a, b);
  CHECK_FALSE(m.reference);
  CHECK(m.conservative);
  CHECK(m.adaptive.verdict == core::PairVerdict::Apart);
  CHECK(m.adaptive.deepestLevel == 0);
  CHECK(m.adaptive.runs == 1);
}

TEST_CASE("faces touching across the view are apart_at_limit, with the region named") {
  // Gap 0: the blocks touch on a face that stands along the view, which no pixel of any
  // frame sees from its centre; no gap is certified, so the pair is refined to the limit.
  const auto [a, b] = diagonalPair(0.0);
  core::RefineLimits limits;
  limits.maxLevel = 2;
  const Modes m = runModes(a, b, limits);
  CHECK_FALSE(m.reference);
  CHECK(m.conservative);
  CHECK(m.adaptive.verdict == core::PairVerdict::ApartAtLimit);
  CHECK(m.adaptive.deepestLevel == 2);
  CHECK(m.adaptive.runs <= limits.maxRuns);
  REQUIRE_FALSE(m.adaptive.unresolved.isEmpty());
  // The touching face runs through the origin.
  CHECK(m.adaptive.unresolved.min.x() <= 0.0);
  CHECK(m.adaptive.unresolved.max.x() >= 0.0);
  CHECK(m.adaptive.unresolved.min.y() <= 0.0);
  CHECK(m.adaptive.unresolved.max.y() >= 0.0);
}

TEST_CASE("a deep overlap is a contact in the request's frame, without refinement") {
  const auto a = boxBetween({-0.6, -0.6, -0.3}, {0.1, 0.6, 0.3});
  const auto b = boxBetween({-0.1, -0.6, -0.3}, {0.6, 0.6, 0.3});
  const Modes m = runModes(a, b);
  CHECK(m.reference);
  CHECK(m.conservative);
  CHECK(m.adaptive.verdict == core::PairVerdict::Collide);
  CHECK(m.adaptive.deepestLevel == 0);
  CHECK(m.adaptive.runs == 1);  // the reference run alone: no grown blocks drawn
}

TEST_CASE("bad refine limits are refused, naming the rules") {
  core::RefineLimits limits;
  limits.factor = 1;
  CHECK_THROWS_WITH(core::AdaptivePairTester(limits), Catch::Contains("factor >= 2"));
}

TEST_CASE("a touch in the request's frame is refined and is the contact when no level is allowed") {
  // Boxes stacked along the view, touching on the plane z = 0: the reference run sees them meet
  // with no depth between them, a touch within rounding, not a deep contact.
  const auto a = boxBetween({-0.6, -0.6, -0.3}, {0.6, 0.6, 0.0});
  const auto b = boxBetween({-0.5, -0.5, 0.0}, {0.5, 0.5, 0.3});
  core::RefineLimits limits;
  limits.maxLevel = 0;
  const Modes flat = runModes(a, b, limits);
  CHECK(flat.reference);
  CHECK(flat.adaptive.verdict == core::PairVerdict::Collide);
  REQUIRE(flat.adaptive.contact);
  CHECK(flat.adaptive.contact->contact.maxDepth == 0.0);
  CHECK(flat.adaptive.contactLevel == 0);
  CHECK(flat.adaptive.runs == 1);  // no level to refine to: the touch is the answer, no grown
                                   // blocks are drawn
  limits.maxLevel = 1;
  const Modes refined = runModes(a, b, limits);
  CHECK(refined.adaptive.verdict == core::PairVerdict::Collide);
  // A touch is refined like a miss: the contact comes from a level-1 tile.
  CHECK(refined.adaptive.deepestLevel == 1);
  CHECK(refined.adaptive.contactLevel == 1);
  CHECK(refined.adaptive.runs > 2);
}

TEST_CASE("faces touching across the view refined one level: the tiles holding both are drawn") {
  // Level 0 leaves the region of the common box of the cubes, x and y in +-0.6 sqrt(1/2) =
  // +-0.4243, grown by two growths of (0.5 + 2/256) * 0.125: +-0.5512. Level 1 tiles it in
  // 16-pixel tiles of 0.125 / 4 pixels, 0.5 wide, from -0.5512: columns (and rows) from -0.5512,
  // -0.0512 and 0.4488 (the last one cut at the edge). A (x + y <= 0) and B (x + y >= 0) both
  // reach into three tiles, (1, 0), (0, 1) and (1, 1); A has no point beyond x or y = 0.4243.
  const auto [a, b] = diagonalPair(0.0);
  core::RefineLimits limits;
  limits.maxLevel = 1;
  limits.tileSide = 16;
  const Modes m = runModes(a, b, limits);
  CHECK(m.adaptive.verdict == core::PairVerdict::ApartAtLimit);
  CHECK(m.adaptive.deepestLevel == 1);
  // The reference and the conservative run at level 0, then both runs in each of the 3 tiles.
  CHECK(m.adaptive.runs == 2 + 3 * 2);
  // Every point of the touching face, (-0.4243, 0.4243) to (0.4243, -0.4243), is a contact
  // no frame sees: the unresolved region holds it ...
  const double end = 0.6 * std::sqrt(0.5);
  CHECK(m.adaptive.unresolved.min.x() <= -end);
  CHECK(m.adaptive.unresolved.max.x() >= end);
  CHECK(m.adaptive.unresolved.min.y() <= -end);
  CHECK(m.adaptive.unresolved.max.y() >= end);
  // ... within two level-1 growths of the cubes' common box.
  const double margin = 2.0 * (0.5 + 2.0 / 256.0) * 0.125 / 4.0 + 1e-12;
  CHECK(m.adaptive.unresolved.min.x() >= -end - margin);
  CHECK(m.adaptive.unresolved.max.x() <= end + margin);
}

TEST_CASE("a run limit with room for every tile leaves the region the tiles reported") {
  // Touching along x = y, the face ends in the top right corner of level 0's region, so the
  // last tile in row order holds both cubes and is drawn. A limit one above the runs the search
  // makes is reached only after the last tile: nothing is left to mark unresolved.
  const auto [a, b] = diagonalPair(0.0, -1.0);
  core::RefineLimits limits;
  limits.maxLevel = 1;
  limits.tileSide = 12;
  const Modes free = runModes(a, b, limits);
  REQUIRE(free.adaptive.verdict == core::PairVerdict::ApartAtLimit);
  limits.maxRuns = free.adaptive.runs + 1;
  const Modes capped = runModes(a, b, limits);
  CHECK(capped.adaptive.verdict == core::PairVerdict::ApartAtLimit);
  CHECK(capped.adaptive.runs == free.adaptive.runs);
  CHECK(capped.adaptive.unresolved.min == free.adaptive.unresolved.min);
  CHECK(capped.adaptive.unresolved.max == free.adaptive.unresolved.max);
  // Each tile's region is within two level-1 growths of the cubes' common box.
  const double bound = 0.6 * std::sqrt(0.5) + 2.0 * (0.5 + 2.0 / 256.0) * 0.125 / 4.0 + 1e-12;
  CHECK(capped.adaptive.unresolved.max.x() <= bound);
  CHECK(capped.adaptive.unresolved.max.y() <= bound);
}

TEST_CASE("the run limit caps the collidePair calls of a deep refinement") {
  // Touching faces refined in 4-pixel tiles down to level 6: the limit, not the levels, ends
  // the search; no tile is started without room for its two runs.
  const auto [a, b] = diagonalPair(0.0, -1.0);
  for (const int maxRuns : {4, 6, 8, 12, 16}) {
    INFO("maxRuns " << maxRuns);
    core::RefineLimits limits;
    limits.tileSide = 4;
    limits.maxRuns = maxRuns;
    const Modes m = runModes(a, b, limits);
    CHECK(m.adaptive.verdict == core::PairVerdict::ApartAtLimit);
    CHECK(m.adaptive.runs <= maxRuns);
    CHECK(m.adaptive.runs >= maxRuns - 1);
  }
}

TEST_CASE("pair mode names: each parses to its own mode and nothing else parses") {
  // pairModeNames lists the modes in the enum's order, each by toString.
  const std::vector<std::string> names = core::pairModeNames();
  CHECK(names == std::vector<std::string>{"reference", "adaptive", "conservative", "skip-apart"});
  const core::PairMode modes[] = {core::PairMode::Reference, core::PairMode::Adaptive,
                                  core::PairMode::Conservative, core::PairMode::SkipApart};
  for (const core::PairMode mode : modes) {
    CAPTURE(core::toString(mode));
    CHECK(core::parsePairMode(core::toString(mode)) == mode);
  }
  // Names are matched exactly: another case, a prefix or an unknown word is no mode.
  CHECK_FALSE(core::parsePairMode("Reference"));
  CHECK_FALSE(core::parsePairMode("skip"));
  CHECK_FALSE(core::parsePairMode(""));
  CHECK_FALSE(core::parsePairMode("exact"));
}
