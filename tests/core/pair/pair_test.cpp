// The pair algorithm on the CPU device: every case from constructed geometry, touching,
// symmetry, the MOR variants, the contact region, and the early out. Over 400 lines: each case
// needs its own constructed pair, and they read best side by side.

#include <catch2/catch.hpp>
#include <optional>
#include <random>
#include <set>

#include "pair_test_support.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/command_stream.hpp"

using namespace recode;
using core::MorMode;
using Eigen::Vector3d;
using test::boxBetween;
using test::caseAt;
using test::flippedAndMoved;
using test::frameZ;
using test::moved;
using test::runPair;

TEST_CASE("slabs at every order of their ends give the table's case on every pixel") {
  // Two boxes covering the whole 2x2 frame, seen along z. World z levels 0..5 map to depths
  // many steps apart, so equal levels give equal depths and different levels different ones.
  const core::FrameSpec frame = frameZ(-1, -1, 1, 1, 2, 2);
  int checked = 0;
  for (int a0 = 0; a0 < 6; ++a0)
    for (int a1 = a0 + 1; a1 < 6; ++a1)
      for (int b0 = 0; b0 < 6; ++b0)
        for (int b1 = b0 + 1; b1 < 6; ++b1) {
          const auto a = boxBetween({-1.5, -1.5, double(a0)}, {1.5, 1.5, double(a1)});
          const auto b = boxBetween({-1.5, -1.5, double(b0)}, {1.5, 1.5, double(b1)});
          // Depth grows as z falls: the near end of [z0, z1] is z1.
          const int expected = core::caseFromIntervals(core::DepthInterval{10u - a1, 10u - a0},
                                                       core::DepthInterval{10u - b1, 10u - b0});
          const core::PairResult r = runPair(a, b, frame, MorMode::Full, true, false);
          INFO("A z [" << a0 << ", " << a1 << "], B z [" << b0 << ", " << b1 << "]");
          for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
              REQUIRE(caseAt(r, x, y) == expected);
          CHECK(r.collide == core::isInterfering(expected));
          CHECK(r.interferingPixels == (r.collide ? 4 : 0));
          ++checked;
        }
  CHECK(checked == 225);
}

TEST_CASE("a contact region's pixel count and area are those of the interfering pixels") {
  // A covers the left column of the frame, B all of it, their z ranges overlapping: the two
  // pixels of the left column interfere. Pixels are 1 x 1 world units on the 2 x 2 frame and
  // 0.5 x 1 on the 4 x 2 one (the same window), so the area is the count times that.
  const auto a = boxBetween({-1.5, -1.5, 0.0}, {-0.2, 1.5, 2.0});
  const auto b = boxBetween({-1.5, -1.5, 1.0}, {1.5, 1.5, 3.0});
  const core::PairResult square = runPair(a, b, frameZ(-1, -1, 1, 1, 2, 2), MorMode::Full);
  REQUIRE(square.interferingPixels == 2);
  CHECK(square.contact.pixels == 2);
  CHECK(square.contact.area == 2.0);
  const core::PairResult narrow = runPair(a, b, frameZ(-1, -1, 1, 1, 4, 2), MorMode::Full);
  REQUIRE(narrow.interferingPixels == 2 * 2);
  CHECK(narrow.contact.pixels == 4);
  CHECK(narrow.contact.area == 4 * 0.5 * 1.0);
}

TEST_CASE("A only, B only and neither on one frame") {
  // A covers the left column, B the bottom row: (0,0) both, (0,1) A only, (1,0) B only.
  const core::FrameSpec frame = frameZ(-1, -1, 1, 1, 2, 2);
  const auto a = boxBetween({-1.5, -1.5, 0.0}, {-0.2, 1.5, 2.0});
  const auto b = boxBetween({-1.5, -1.5, 1.0}, {1.5, -0.2, 3.0});
  const core::PairResult r = runPair(a, b, frame, MorMode::Full);
  CHECK(caseAt(r, 0, 1) == 1);
  CHECK(caseAt(r, 1, 0) == 8);
  CHECK(caseAt(r, 1, 1) == 0);
  CHECK(caseAt(r, 0, 0) == 6);  // B's far end (z = 1) inside A, its near end in front
  CHECK(r.collide);
  CHECK(r.caseCounts[0] + r.caseCounts[1] + r.caseCounts[8] + r.caseCounts[6] == 4);
}

namespace {

struct CaseScene {
  int expectedCase;
  const char* what;
  core::TriangleMesh a, b;
};

}  // namespace

TEST_CASE("one constructed cone/box configuration per case 1-8") {
  // A: a cone of radius 1 and height 2 standing on z = 0 on the origin; the pixel under test
  // is the one whose centre is (0.05, 0.05), next to the apex, seen along z.
  const core::TriangleMesh cone = core::makeCone(1.0, 2.0, 48);
  const core::FrameSpec frame = frameZ(-2, -2, 2, 2, 40, 40);
  const int px = 20, py = 20;  // centre (0.05, 0.05)
  const std::vector<CaseScene> scenes = {
      {1, "B beside A", cone, boxBetween({1.5, -0.5, 0.0}, {1.9, 0.5, 1.0})},
      {2, "B below A", cone, boxBetween({-0.5, -0.5, -3.0}, {0.5, 0.5, -1.0})},
      {3, "B's top inside A, its bottom below", cone,
       boxBetween({-0.3, -0.3, -1.0}, {0.3, 0.3, 1.0})},
      {4, "B around A", cone, boxBetween({-1.5, -1.5, -1.0}, {1.5, 1.5, 3.0})},
      {5, "B inside A", cone, boxBetween({-0.2, -0.2, 0.5}, {0.2, 0.2, 1.0})},
      {6, "B's bottom inside A, its top above", cone,
       boxBetween({-0.3, -0.3, 1.0}, {0.3, 0.3, 3.0})},
      {7, "B above A's apex", cone, boxBetween({-0.5, -0.5, 2.5}, {0.5, 0.5, 3.0})},
      {8, "A beside B", moved(cone, {5.0, 0.0, 0.0}),
       boxBetween({-0.5, -0.5, 0.0}, {0.5, 0.5, 1.0})},
  };
  for (const CaseScene& s : scenes) {
    INFO("case " << s.expectedCase << ": " << s.what);
    const core::PairResult r = runPair(s.a, s.b, frame, MorMode::Full, true, false);
    CHECK(caseAt(r, px, py) == s.expectedCase);
    CHECK(r.collide == core::isInterfering(s.expectedCase));
    CHECK(r.caseCounts[static_cast<std::size_t>(s.expectedCase)] > 0);
  }
}

namespace {

// Touching along z at world z = kContact, with the depth range [0, 2^24 - 1] so that one
// world unit is exactly one depth step near the contact. The apexes sit on the pixel centre
// (0.25, 0.25) of an 8x8 frame over [-2, 2]^2.
constexpr double kTop = 16777215.0;
constexpr double kContact = 12000000.0;
const Vector3d kApexXY(0.25, 0.25, 0.0);

core::TriangleMesh lowerBox() {
  return boxBetween({-1.0, -1.0, 0.0}, {1.0, 1.0, kContact});
}
core::TriangleMesh lowerCone() {
  return moved(core::makeCone(1.0, kContact, 32), kApexXY);
}
core::TriangleMesh upperBox(double gap) {
  return boxBetween({-1.0, -1.0, kContact + gap}, {1.0, 1.0, kTop});
}
core::TriangleMesh upperCone(double gap) {
  // Apex down at kContact + gap, base at kTop.
  return flippedAndMoved(core::makeCone(1.0, kTop - kContact - gap, 32),
                         {kApexXY.x(), kApexXY.y(), kTop});
}

}  // namespace

TEST_CASE("touching is interference; one depth step apart is not") {
  const core::FrameSpec frame = frameZ(-2, -2, 2, 2, 8, 8);
  struct Contact {
    const char* what;
    core::TriangleMesh (*lower)();
    core::TriangleMesh (*upper)(double);
    long long touchingPixels;  // pixels where the surfaces meet
  };
  const Contact contacts[] = {
      {"face on face", lowerBox, upperBox, 16},
      {"tip on face", lowerCone, upperBox, 1},
      {"tip on tip", lowerCone, upperCone, 1},
  };
  for (const Contact& c : contacts) {
    INFO(c.what);
    const core::PairResult touching = runPair(c.lower(), c.upper(0.0), frame);
    CHECK(touching.collide);
    CHECK(touching.interferingPixels == c.touchingPixels);
    // The upper block is in front and its far end meets the lower block's near end: case 6.
    CHECK(touching.caseCounts[6] == c.touchingPixels);
    CHECK(touching.contact.maxDepth == 0.0);
    if (c.touchingPixels == 1) {
      CHECK(caseAt(touching, 4, 4) == 6);  // the pixel whose centre is the apex
      REQUIRE(touching.contact.points.size() == 1);
      CHECK(touching.contact.points[0].isApprox(Vector3d(0.25, 0.25, kContact)));
    }
    const core::PairResult apart = runPair(c.lower(), c.upper(1.0), frame);
    CHECK_FALSE(apart.collide);
    CHECK(apart.interferingPixels == 0);
    CHECK(apart.caseCounts[7] == touching.caseCounts[7] + c.touchingPixels);
  }
}

namespace {

core::TriangleMesh randomBlock(std::mt19937& rng) {
  std::uniform_real_distribution<double> size(0.3, 1.2), pos(-0.8, 0.8), angle(-M_PI, M_PI);
  std::uniform_int_distribution<int> kind(0, 4);
  core::TriangleMesh m;
  switch (kind(rng)) {
    case 0:
      m = core::makeCone(size(rng), 2.0 * size(rng), 24);
      break;
    case 1:
      m = core::makeBox(size(rng), size(rng), 0.5 * size(rng));
      break;
    case 2:
      m = core::makeEllipsoid(size(rng), 0.5 * size(rng), size(rng), 16, 8);
      break;
    case 3:
      m = core::makeCappedCone(0.6, 0.2, 1.5, 16, 3);
      break;
    default:
      m = core::makeCylinder(0.15, 2.5 * size(rng), 12);  // a needle
      break;
  }
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Vector3d(pos(rng), pos(rng), pos(rng)));
  t.rotate(Eigen::AngleAxisd(angle(rng), Vector3d::UnitZ()) *
           Eigen::AngleAxisd(angle(rng), Vector3d::UnitX()) *
           Eigen::AngleAxisd(angle(rng), Vector3d::UnitY()));
  return core::transformed(m, t);
}

// The interfering pixels as frame coordinates.
std::set<std::pair<int, int>> interferingSet(const core::PairResult& r) {
  std::set<std::pair<int, int>> out;
  for (int y = r.mor.y0; y < r.mor.y1; ++y)
    for (int x = r.mor.x0; x < r.mor.x1; ++x)
      if (core::isInterfering(caseAt(r, x, y)))
        out.insert({x, y});
  return out;
}

bool contains(const raster::PixelRect& outer, const raster::PixelRect& inner) {
  return inner.empty() || (outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && inner.x1 <= outer.x1 &&
                           inner.y1 <= outer.y1);
}

}  // namespace

TEST_CASE("swapping A and B keeps the verdict and the interfering pixels") {
  std::mt19937 rng(20261122);
  const core::ViewAxis axes[] = {core::ViewAxis::X, core::ViewAxis::Y, core::ViewAxis::Z};
  int collisions = 0;
  for (int i = 0; i < 120; ++i) {
    const core::TriangleMesh a = randomBlock(rng), b = randomBlock(rng);
    core::FrameSpec frame;
    frame.axis = axes[i % 3];
    frame.window = {-3, -3, 3, 3};
    frame.width = frame.height = 48 + 16 * (i % 4);
    const core::PairResult ab = runPair(a, b, frame), ba = runPair(b, a, frame);
    INFO("pair " << i);
    CHECK(ab.collide == ba.collide);
    CHECK(ab.mor == ba.mor);
    CHECK(interferingSet(ab) == interferingSet(ba));
    // The mirrored cases: 3 <-> 6 and 4 <-> 5 swap with the roles; 2 <-> 7 likewise.
    CHECK(ab.caseCounts[3] + ab.caseCounts[6] == ba.caseCounts[3] + ba.caseCounts[6]);
    CHECK(ab.caseCounts[4] == ba.caseCounts[5]);
    CHECK(ab.caseCounts[5] == ba.caseCounts[4]);
    CHECK(ab.caseCounts[2] == ba.caseCounts[7]);
    CHECK(ab.contact.box.isEmpty() == ba.contact.box.isEmpty());
    if (ab.collide) {
      CHECK(ab.contact.box.min.isApprox(ba.contact.box.min, 1e-9));
      CHECK(ab.contact.box.max.isApprox(ba.contact.box.max, 1e-9));
    }
    collisions += ab.collide ? 1 : 0;
  }
  // The generator must produce both outcomes for the test to mean anything.
  CHECK(collisions > 30);
  CHECK(collisions < 110);
}

TEST_CASE("MIN inside MAX inside FULL: same verdict, same interfering pixels, fewer reads") {
  std::mt19937 rng(7);
  int strictlyFewer = 0, overlapping = 0;
  for (int i = 0; i < 80; ++i) {
    const core::TriangleMesh a = randomBlock(rng), b = randomBlock(rng);
    core::FrameSpec frame;
    frame.axis = core::ViewAxis::Z;
    frame.window = {-3, -3, 3, 3};
    frame.width = frame.height = 64;
    const core::PairResult mn = runPair(a, b, frame, MorMode::Min);
    const core::PairResult mx = runPair(a, b, frame, MorMode::Max);
    const core::PairResult full = runPair(a, b, frame, MorMode::Full);
    INFO("pair " << i);
    CHECK(mn.collide == mx.collide);
    CHECK(mx.collide == full.collide);
    CHECK(mn.boxesOverlap == full.boxesOverlap);
    if (!mn.boxesOverlap)
      continue;
    ++overlapping;
    CHECK(contains(mx.mor, mn.mor));
    CHECK(contains(full.mor, mx.mor));
    CHECK(interferingSet(mn) == interferingSet(mx));
    CHECK(interferingSet(mx) == interferingSet(full));
    CHECK(mn.stencilPixelsRead <= mx.stencilPixelsRead);
    CHECK(mx.stencilPixelsRead <= full.stencilPixelsRead);
    CHECK(full.stencilPixelsRead == 64 * 64);
    strictlyFewer += mn.stencilPixelsRead < mx.stencilPixelsRead ? 1 : 0;
    // Cases that need both blocks (2-7) lie in MIN: the wider MORs only add 0, 1 and 8.
    for (int c = 2; c <= 7; ++c)
      CHECK(mn.caseCounts[static_cast<std::size_t>(c)] ==
            full.caseCounts[static_cast<std::size_t>(c)]);
  }
  CHECK(overlapping > 40);
  CHECK(strictlyFewer > overlapping / 2);
}

TEST_CASE("the MAX MOR is the bounding rectangle of both footprints") {
  // 8x8 pixels over [0, 8]^2: pixel i's centre is i + 0.5. A spans [1, 4] in x and y (pixels
  // 1..3), B [3, 6] x [2, 7] (pixels 3..5 by 2..6); they overlap, and neither holds the other.
  const core::FrameSpec frame = frameZ(0, 0, 8, 8, 8, 8);
  const auto a = boxBetween({1, 1, 0}, {4, 4, 1});
  const auto b = boxBetween({3, 2, 0.5}, {6, 7, 2});
  const raster::PixelRect both{1, 1, 6, 7};
  CHECK(runPair(a, b, frame, MorMode::Max).mor == both);
  CHECK(runPair(b, a, frame, MorMode::Max).mor == both);
  CHECK(runPair(a, b, frame, MorMode::Min).mor == raster::PixelRect{3, 2, 4, 4});
}

TEST_CASE("overlapping boxes: the contact region is the intersection box at pixel centres") {
  // A [-1, 1]^3, B [0, 2] x [0, 2] x [0.5, 3]: they share [0, 1] x [0, 1] x [0.5, 1].
  // 40x40 pixels over [-2, 2]^2: pixel size 0.1, centres at 0.05 + 0.1 k.
  const auto a = boxBetween({-1, -1, -1}, {1, 1, 1});
  const auto b = boxBetween({0, 0, 0.5}, {2, 2, 3});
  const core::PairResult r = runPair(a, b, frameZ(-2, -2, 2, 2, 40, 40));
  REQUIRE(r.collide);
  CHECK(r.interferingPixels == 100);  // centres 0.05 .. 0.95 in x and y
  CHECK(r.caseCounts[6] == 100);      // B's far end (z = 0.5) inside A, its near end above
  CHECK(r.contact.points.size() == 100);
  CHECK(r.contact.area == Approx(100 * 0.01));
  // Depth range [-1, 3]: one step is 4 / (2^24 - 1) world units.
  const double step = 4.0 / 16777215.0;
  CHECK(r.contact.maxDepth == Approx(0.5).margin(2 * step));
  CHECK(r.contact.box.min.x() == Approx(0.05));
  CHECK(r.contact.box.max.x() == Approx(0.95));
  CHECK(r.contact.box.min.y() == Approx(0.05));
  CHECK(r.contact.box.max.y() == Approx(0.95));
  CHECK(r.contact.box.min.z() == Approx(0.5).margin(step));
  CHECK(r.contact.box.max.z() == Approx(1.0).margin(step));
  for (const Vector3d& p : r.contact.points)
    CHECK(p.z() == Approx(0.75).margin(step));
  // MIN MOR: the projected boxes share [0, 1]^2, pixel centres 0.05 .. 0.95: columns 20..29.
  CHECK(r.mor == raster::PixelRect{20, 20, 30, 30});
  CHECK(r.stencilPixelsRead == 100);
  CHECK(r.contactRect == raster::PixelRect{20, 20, 30, 30});
  CHECK(r.depthPixelsRead == 200);
}

TEST_CASE("without the contact passes the verdict, cases and area are the same") {
  const auto a = boxBetween({-1, -1, -1}, {1, 1, 1});
  const auto b = boxBetween({0, 0, 0.5}, {2, 2, 3});
  const auto frame = frameZ(-2, -2, 2, 2, 40, 40);
  const core::PairResult with = runPair(a, b, frame, MorMode::Min, true);
  const core::PairResult without = runPair(a, b, frame, MorMode::Min, false);
  CHECK(with.caseCounts == without.caseCounts);
  CHECK(without.contact.area == with.contact.area);
  CHECK(without.contact.points.empty());
  CHECK(without.contact.box.isEmpty());
  CHECK(without.depthPixelsRead == 0);
}

TEST_CASE("boxes apart: the early out draws and reads nothing") {
  const auto frame = frameZ(-4, -4, 4, 4, 32, 32);
  // Apart on the image plane.
  const core::PairResult side = runPair(boxBetween({-3, -1, -1}, {-1, 1, 1}),
                                        boxBetween({1, -1, -1}, {3, 1, 1}), frame, MorMode::Full);
  CHECK_FALSE(side.boxesOverlap);
  CHECK_FALSE(side.collide);
  CHECK(side.stencilPixelsRead == 0);
  CHECK(side.mor.empty());
  // Overlapping on the image plane, apart in depth.
  const core::PairResult depth =
      runPair(boxBetween({-1, -1, -3}, {1, 1, -1}), boxBetween({-1, -1, 1}, {1, 1, 3}), frame);
  CHECK_FALSE(depth.boxesOverlap);
  CHECK(depth.stencilPixelsRead == 0);
}

TEST_CASE("the box test never changes the verdict or the interfering pixels") {
  std::mt19937 rng(31);
  int skipped = 0;
  for (int i = 0; i < 150; ++i) {
    const core::TriangleMesh a = randomBlock(rng), b = randomBlock(rng);
    const auto frame = frameZ(-3, -3, 3, 3, 40, 40);
    const core::PairResult on = runPair(a, b, frame, MorMode::Full, true, true);
    const core::PairResult off = runPair(a, b, frame, MorMode::Full, true, false);
    INFO("pair " << i);
    CHECK(on.collide == off.collide);
    if (!on.boxesOverlap) {
      ++skipped;
      CHECK(off.interferingPixels == 0);
    } else {
      CHECK(interferingSet(on) == interferingSet(off));
    }
  }
  CHECK(skipped > 10);
}

TEST_CASE("the algorithm talks only to the device: a recorded stream replays to the same bits") {
  std::mt19937 rng(99);
  for (int i = 0; i < 20; ++i) {
    const core::TriangleMesh a = randomBlock(rng), b = randomBlock(rng);
    const auto frame = frameZ(-3, -3, 3, 3, 48, 48);
    raster::CpuDevice inner(48, 48);
    raster::RecordingDevice recorder(inner);
    core::PairRequest request;
    request.frame = frame;
    const core::PairResult r = core::collidePair(recorder, a, b, request);
    raster::CpuDevice fresh(48, 48);
    raster::replay(recorder.stream().commands, fresh);
    const raster::PixelRect all{0, 0, 48, 48};
    CHECK(fresh.readStencil(all) == inner.readStencil(all));
    CHECK(fresh.readDepth(all) == inner.readDepth(all));
    if (r.boxesOverlap)
      CHECK_FALSE(recorder.stream().commands.empty());
  }
}

TEST_CASE("a device of the wrong size is refused") {
  raster::CpuDevice device(10, 10);
  core::PairRequest request;
  request.frame = frameZ(-1, -1, 1, 1, 20, 20);
  const auto box = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  CHECK_THROWS_WITH(core::collidePair(device, box, box, request),
                    Catch::Contains("device is 10x10 but the pair's frame is 20x20"));
}

TEST_CASE("random axis-aligned boxes: every pixel's case matches the boxes' own intervals") {
  // Box sides on pixel edges (multiples of 0.25 on a 32x32 frame over [-4, 4]^2), so no pixel
  // centre lies on an edge; z on the same grid, so equal z gives equal depth and different z
  // depths many steps apart. The expected case comes from the boxes, not from the device.
  std::mt19937 rng(4242);
  std::uniform_int_distribution<int> grid(-16, 16);
  const auto frame = frameZ(-4, -4, 4, 4, 32, 32);
  long long interfering = 0, pixels = 0;
  for (int i = 0; i < 150; ++i) {
    Vector3d lo[2], hi[2];
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 3; ++d) {
        int u = grid(rng), v = grid(rng);
        while (u == v)
          v = grid(rng);
        lo[k][d] = 0.25 * std::min(u, v);
        hi[k][d] = 0.25 * std::max(u, v);
      }
    const core::PairResult r = runPair(boxBetween(lo[0], hi[0]), boxBetween(lo[1], hi[1]), frame,
                                       MorMode::Full, true, false);
    INFO("pair " << i);
    long long interferingHere = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const double cx = -4 + 0.25 * (x + 0.5), cy = -4 + 0.25 * (y + 0.5);
        std::optional<core::DepthInterval> iv[2];
        for (int k = 0; k < 2; ++k)
          if (lo[k].x() < cx && cx < hi[k].x() && lo[k].y() < cy && cy < hi[k].y())
            // Depth order is -z; shift to stay unsigned (z is in [-4, 4] on a 0.25 grid).
            iv[k] = core::DepthInterval{static_cast<std::uint32_t>(100 - 4 * hi[k].z()),
                                        static_cast<std::uint32_t>(100 - 4 * lo[k].z())};
        const int expected = core::caseFromIntervals(iv[0], iv[1]);
        if (caseAt(r, x, y) != expected)
          FAIL_CHECK("pixel (" << x << ", " << y << "): device case " << caseAt(r, x, y)
                               << ", boxes say " << expected);
        interferingHere += core::isInterfering(expected) ? 1 : 0;
        ++pixels;
      }
    CHECK(r.interferingPixels == interferingHere);
    CHECK(r.collide == (interferingHere > 0));
    interfering += interferingHere;
  }
  CHECK(pixels == 150 * 1024);
  CHECK(interfering > 1000);  // the generator must produce plenty of overlap
}
