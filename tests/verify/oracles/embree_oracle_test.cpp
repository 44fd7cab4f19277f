// The Embree interval oracle: hand-made box pairs whose every pixel is known by hand, its
// power to fail (corrupted case maps, a shrunken MOR), the tie rule on its own, its depth
// tolerance against the device's own depth buffer, and the generated pair suite. Over 400
// lines: the hand-made pairs spell out their expected pixels.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <map>
#include <string>

#include "pair_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/embree_oracle.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;
using core::DepthInterval;
using Eigen::Vector3d;
using test::boxBetween;
using test::runPair;

namespace {

constexpr std::uint32_t kFar = 16777215;  // 2^24 - 1

// A 16 x 16 frame over [0, 16]^2 along z: one world unit per pixel, pixel i's centre at
// i + 0.5, so box faces at integer coordinates lie half a pixel from every centre.
core::FrameSpec frame16() {
  return test::frameZ(0.0, 0.0, 16.0, 16.0, 16, 16);
}

bool inRange(int v, int lo, int hi) {
  return v >= lo && v <= hi;
}

// The boxes below have integer corners and sides of odd-by-even length, so neither face
// diagonal passes within 1/256 px of a pixel centre (a diagonal's edge function at the centres
// is a half-integer), and their outlines lie half a pixel from the centres: no pixel is an
// edge sample.
//   A = [2, 10] x [2, 9]: pixels i 2..9, j 2..8 (56)
//   B = [6, 13] x [5, 13]: pixels i 6..12, j 5..12 (56)
//   both: i 6..9, j 5..8 (16)
bool inA(int i, int j) {
  return inRange(i, 2, 9) && inRange(j, 2, 8);
}
bool inB(int i, int j) {
  return inRange(i, 6, 12) && inRange(j, 5, 12);
}

}  // namespace

TEST_CASE("embree oracle: two boxes, every pixel's intervals and case by hand") {
  // z: A in [0, 2], B in [1, 3]; the pair's depth maps z = 3 to 0 and z = 0 to 1, so
  // depth = (3 - z) / 3: A spans [1/3, 1], B spans [0, 2/3]; 2^24 - 1 = 3 * 5592405.
  const core::TriangleMesh a = boxBetween({2, 2, 0}, {10, 9, 2});
  const core::TriangleMesh b = boxBetween({6, 5, 1}, {13, 13, 3});
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  const verify::EmbreeSamples s = oracle.sample(frame, a, b, {0, 0, 16, 16});
  REQUIRE(s.rect == raster::PixelRect{0, 0, 16, 16});
  REQUIRE(s.cases.size() == 256);
  CHECK(s.rays == 4 * 256);
  CHECK(s.fallbackPixels == 0);
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * 16 + i);
      CAPTURE(i, j);
      CHECK(s.nearEdge[k] == 0);
      REQUIRE(s.a[k].has_value() == inA(i, j));
      REQUIRE(s.b[k].has_value() == inB(i, j));
      if (s.a[k]) {
        CHECK(s.a[k]->min == 5592405u);
        CHECK(s.a[k]->max == kFar);
      }
      if (s.b[k]) {
        CHECK(s.b[k]->min == 0u);
        CHECK(s.b[k]->max == 2u * 5592405u);
      }
      // B's near end in front of A's, its far end inside A: "B enters A from the front".
      const int expected = inA(i, j) ? (inB(i, j) ? 6 : 1) : (inB(i, j) ? 8 : 0);
      CHECK(int{s.cases[k]} == expected);
    }
  }

  // The device over the whole frame agrees on every pixel; with the minimal MOR only the 16
  // pixels under both blocks are examined.
  const core::PairResult full = runPair(a, b, frame, core::MorMode::Full);
  const verify::EmbreeReport all = oracle.check(frame, a, b, full);
  CHECK(all.counts.pixels == 256);
  CHECK(all.counts.agree == 256);
  CHECK(all.rays == 4 * 256);
  const core::PairResult min = runPair(a, b, frame);
  const verify::EmbreeReport some = oracle.check(frame, a, b, min);
  CHECK(some.counts.pixels == 16);
  CHECK(some.counts.agree == 16);
  CHECK(some.unexplained.empty());
}

TEST_CASE("embree oracle: faces touching exactly interfere, and a tie explains the near miss") {
  // A's top face and B's bottom face are the plane z = 1; depth = (2 - z) / 2, so the shared
  // face is at depth 1/2, whose 24-bit value 8388607.5 rounds half to even to 8388608.
  const core::TriangleMesh a = boxBetween({2, 2, 0}, {10, 9, 1});
  const core::TriangleMesh b = boxBetween({6, 5, 1}, {13, 13, 2});
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  const verify::EmbreeSamples s = oracle.sample(frame, a, b, {7, 6, 8, 7});
  REQUIRE(s.cases.size() == 1);
  REQUIRE(s.a[0].has_value());
  REQUIRE(s.b[0].has_value());
  CHECK(s.a[0]->min == 8388608u);
  CHECK(s.a[0]->max == kFar);
  CHECK(s.b[0]->min == 0u);
  CHECK(s.b[0]->max == 8388608u);
  CHECK(int{s.cases[0]} == 6);  // Bmin < Amin <= Bmax <= Amax: touching counts

  core::PairResult r = runPair(a, b, frame);
  REQUIRE(r.mor == raster::PixelRect{6, 5, 10, 9});
  const verify::EmbreeReport clean = oracle.check(frame, a, b, r);
  CHECK(clean.counts.agree == 16);
  CHECK(r.caseCounts[6] == 16);

  // "B in front of A" (Bmax < Amin) is one step away from the oracle's Bmax = Amin: a tie.
  r.caseMap.at(7, 6) = 7;
  // "A spans B" needs Amin <= Bmin, 8388608 steps away: unexplained.
  r.caseMap.at(8, 7) = 5;
  const verify::EmbreeReport bad = oracle.check(frame, a, b, r);
  CHECK(bad.counts.pixels == 16);
  CHECK(bad.counts.agree == 14);
  CHECK(bad.counts.ties == 1);
  CHECK(bad.counts.edges == 0);
  CHECK(bad.counts.unexplained == 1);
  REQUIRE(bad.unexplained.size() == 1);
  CHECK(bad.unexplained[0].x == 8);
  CHECK(bad.unexplained[0].y == 7);
  CHECK(bad.unexplained[0].deviceCase == 5);
  CHECK(bad.unexplained[0].oracleCase == 6);
}

TEST_CASE("embree oracle: a corrupted case and a shrunken MOR are reported unexplained") {
  // A in z [1, 2], B in z [0, 3]: depth = (3 - z) / 3, so A spans [1/3, 2/3] and B [0, 1]:
  // B spans A ("case 4") under both blocks, by millions of steps.
  const core::TriangleMesh a = boxBetween({2, 2, 1}, {10, 9, 2});
  const core::TriangleMesh b = boxBetween({6, 5, 0}, {13, 13, 3});
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  const core::PairResult r = runPair(a, b, frame);
  REQUIRE(r.mor == raster::PixelRect{6, 5, 10, 9});
  REQUIRE(r.caseCounts[4] == 16);
  const verify::EmbreeReport clean = oracle.check(frame, a, b, r);
  CHECK(clean.counts.agree == 16);
  CHECK(clean.counts.unexplained == 0);

  SECTION("one pixel flipped from 4 to 7") {
    core::PairResult bad = r;
    bad.caseMap.at(7, 6) = 7;
    const verify::EmbreeReport rep = oracle.check(frame, a, b, bad);
    CHECK(rep.counts.pixels == 16);
    CHECK(rep.counts.agree == 15);
    CHECK(rep.counts.ties == 0);
    CHECK(rep.counts.edges == 0);
    CHECK(rep.counts.unexplained == 1);
    REQUIRE(rep.unexplained.size() == 1);
    const verify::PixelDisagreement& d = rep.unexplained[0];
    CHECK(d.x == 7);
    CHECK(d.y == 6);
    CHECK(d.deviceCase == 7);
    CHECK(d.oracleCase == 4);
    CHECK(d.kind == verify::DisagreementKind::Unexplained);
    REQUIRE(d.a.has_value());
    REQUIRE(d.b.has_value());
    CHECK(d.a->min == 5592405u);
    CHECK(d.a->max == 2u * 5592405u);
    CHECK(d.b->min == 0u);
    CHECK(d.b->max == kFar);
  }

  SECTION("the MOR's right column dropped: its interfering pixels were missed") {
    core::PairResult bad = r;
    bad.mor.x1 -= 1;
    std::vector<std::uint8_t> kept;
    for (int y = r.mor.y0; y < r.mor.y1; ++y)
      for (int x = r.mor.x0; x < bad.mor.x1; ++x)
        kept.push_back(r.caseMap.at(x, y));
    bad.caseMap = raster::PixelBuffer<std::uint8_t>(bad.mor, std::move(kept));
    const verify::EmbreeReport rep = oracle.check(frame, a, b, bad);
    CHECK(rep.counts.pixels == 16);  // the dropped column is still under both footprints
    CHECK(rep.counts.agree == 12);
    CHECK(rep.counts.unexplained == 4);
    REQUIRE(rep.unexplained.size() == 4);
    for (int k = 0; k < 4; ++k) {
      const verify::PixelDisagreement& d = rep.unexplained[static_cast<std::size_t>(k)];
      CHECK(d.x == 9);
      CHECK(d.y == 5 + k);
      CHECK(d.deviceCase == verify::kOutsideMor);
      CHECK(d.oracleCase == 4);
    }
  }
}

TEST_CASE("embree oracle: a disagreement on a pixel centre that lies on an edge is an edge") {
  // B's left face at x = 6.5 passes through the centres of column 6, which the fill rule gives
  // to B (left edges are inclusive).
  const core::TriangleMesh a = boxBetween({2, 2, 1}, {10, 9, 2});
  const core::TriangleMesh b = boxBetween({6.5, 5, 0}, {13, 13, 3});
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  core::PairResult r = runPair(a, b, frame);
  REQUIRE(r.mor == raster::PixelRect{6, 5, 10, 9});
  const verify::EmbreeReport clean = oracle.check(frame, a, b, r);
  CHECK(clean.counts.pixels == 16);
  CHECK(clean.counts.unexplained == 0);
  CHECK(clean.counts.agree + clean.counts.edges == 16);
  const verify::EmbreeSamples s = oracle.sample(frame, a, b, {6, 6, 8, 7});
  CHECK(s.nearEdge == std::vector<std::uint8_t>{1, 0});

  // Pixel (6, 6) is on the edge, (7, 6) is not. "B in front of A" is neither block's
  // coverage nor within a tie of B spanning A, so only the edge can explain it.
  r.caseMap.at(6, 6) = 7;
  r.caseMap.at(7, 6) = 7;
  const verify::EmbreeReport rep = oracle.check(frame, a, b, r);
  CHECK(rep.counts.pixels == 16);
  CHECK(rep.counts.edges >= 1);
  CHECK(rep.counts.unexplained == 1);
  REQUIRE(rep.unexplained.size() == 1);
  CHECK(rep.unexplained[0].x == 7);
  CHECK(rep.unexplained[0].y == 6);
}

TEST_CASE("embree oracle: outside the MOR and where the box test skipped the passes") {
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  SECTION("footprints apart: nothing to examine") {
    const core::TriangleMesh a = boxBetween({1, 1, 0}, {4, 4, 1});
    const core::TriangleMesh b = boxBetween({8, 8, 0}, {12, 12, 1});
    const core::PairResult r = runPair(a, b, frame);
    REQUIRE_FALSE(r.boxesOverlap);
    const verify::EmbreeReport rep = oracle.check(frame, a, b, r);
    CHECK(rep.counts.pixels == 0);
    CHECK(rep.rays == 0);
  }
  SECTION("footprints overlap, depths apart: the 16 shared pixels hold B in front of A") {
    const core::TriangleMesh a = boxBetween({2, 2, 0}, {10, 9, 1});
    const core::TriangleMesh b = boxBetween({6, 5, 2}, {13, 13, 3});
    const core::PairResult r = runPair(a, b, frame);
    REQUIRE_FALSE(r.boxesOverlap);
    REQUIRE(r.mor.empty());
    const verify::EmbreeReport rep = oracle.check(frame, a, b, r);
    CHECK(rep.counts.pixels == 16);
    CHECK(rep.counts.agree == 16);
  }
  SECTION("a result claiming no passes for blocks that interfere is caught") {
    const core::TriangleMesh a = boxBetween({2, 2, 0}, {10, 9, 2});
    const core::TriangleMesh b = boxBetween({6, 5, 1}, {13, 13, 3});
    core::PairResult r = runPair(a, b, frame);
    r.mor = {};
    r.caseMap = {};
    r.boxesOverlap = false;
    const verify::EmbreeReport rep = oracle.check(frame, a, b, r);
    CHECK(rep.counts.pixels == 16);
    CHECK(rep.counts.unexplained == 16);
    CHECK(rep.unexplained.size() == verify::kMaxListedDisagreements);
  }
}

TEST_CASE("embree oracle: results that cannot belong to the pair are rejected") {
  const core::TriangleMesh a = boxBetween({2, 2, 0}, {10, 9, 2});
  const core::TriangleMesh b = boxBetween({6, 5, 1}, {13, 13, 3});
  const core::FrameSpec frame = frame16();
  verify::EmbreeOracle oracle;
  const core::PairResult r = runPair(a, b, frame);
  core::PairResult shortMap = r;
  shortMap.caseMap.data.pop_back();
  CHECK_THROWS_WITH(oracle.check(frame, a, b, shortMap),
                    Catch::Contains("case map has 15 pixels but its MOR has 16"));
  core::PairResult outside = r;
  outside.mor = {10, 10, 18, 12};
  outside.caseMap.data.assign(16, 0);
  CHECK_THROWS_WITH(oracle.check(frame, a, b, outside), Catch::Contains("does not lie in"));
  core::PairResult badCase = r;
  badCase.caseMap.data[3] = 9;
  CHECK_THROWS_WITH(oracle.check(frame, a, b, badCase), Catch::Contains("holds 9 at index 3"));
  const core::TriangleMesh taller = boxBetween({6, 5, 1}, {13, 13, 4});
  CHECK_THROWS_WITH(oracle.check(frame, a, taller, r), Catch::Contains("another pair"));
  core::TriangleMesh broken = a;
  broken.triangles[0][1] = 99;
  CHECK_THROWS_WITH(oracle.check(frame, broken, b, r),
                    Catch::Contains("block A: triangle 0 uses vertex 99"));
}

TEST_CASE("embree oracle: the tie rule moves each end by at most the tolerance") {
  const DepthInterval a{10, 20};
  // B starts 1, 2 or 3 steps behind A's far end: case 2. Each end may move one step, so a
  // gap of two steps closes (A's far end forward, B's near end back) and one of three not.
  CHECK(core::caseFromIntervals(a, DepthInterval{21, 30}) == 2);
  CHECK(verify::caseWithinTolerance(a, DepthInterval{21, 30}, 3, 1));
  CHECK(verify::caseWithinTolerance(a, DepthInterval{22, 30}, 3, 1));
  CHECK_FALSE(verify::caseWithinTolerance(a, DepthInterval{23, 30}, 3, 1));
  CHECK_FALSE(verify::caseWithinTolerance(a, DepthInterval{21, 30}, 3, 0));
  CHECK(verify::caseWithinTolerance(a, DepthInterval{21, 30}, 2, 0));
  // Outside the MOR the device only says "not interfering".
  CHECK(verify::caseWithinTolerance(a, DepthInterval{15, 30}, verify::kOutsideMor, 1) == false);
  CHECK(verify::caseWithinTolerance(a, DepthInterval{20, 30}, verify::kOutsideMor, 1));
  // Presence never moves.
  CHECK_FALSE(verify::caseWithinTolerance(a, std::nullopt, 2, 1));
  CHECK(verify::caseWithinTolerance(a, std::nullopt, 1, 1));
  CHECK_FALSE(verify::caseWithinTolerance(std::nullopt, std::nullopt, 8, 1));
  CHECK_THROWS_WITH(verify::caseWithinTolerance(a, a, 9, 1), Catch::Contains("device case 9"));
  CHECK_THROWS_WITH(verify::caseWithinTolerance(a, a, 3, 9), Catch::Contains("tolerance 9"));
}

namespace {

// One block alone on the device: its nearest and farthest depth and its coverage per pixel.
struct DeviceBlock {
  std::vector<std::uint32_t> nearDepth, farDepth;
  std::vector<std::uint8_t> covered;
};

DeviceBlock renderAlone(const core::TriangleMesh& mesh, const core::OrthoView& view,
                        const raster::PixelRect& rect) {
  raster::CpuDevice device(view.width(), view.height());
  const std::vector<raster::WindowVertex> v = view.toWindow(mesh);
  const std::vector<std::uint32_t> idx = core::triangleIndices(mesh);
  DeviceBlock out;
  device.setCullMode(raster::CullMode::None);
  device.setStencilFunc(raster::CompareFunc::Always, 1, 0xFF);
  device.setStencilOps(raster::Face::Both, {raster::StencilOp::Keep, raster::StencilOp::Keep,
                                            raster::StencilOp::Replace});
  device.clearStencil(0);
  device.clearDepth(1.0);
  device.setDepthFunc(raster::CompareFunc::LEqual);
  device.drawTriangles(v, idx);
  out.nearDepth = device.readDepth(rect);
  out.covered = device.readStencil(rect);
  device.clearDepth(0.0);
  device.setDepthFunc(raster::CompareFunc::GEqual);
  device.drawTriangles(v, idx);
  out.farDepth = device.readDepth(rect);
  return out;
}

std::uint32_t gap(std::uint32_t x, std::uint32_t y) {
  return x > y ? x - y : y - x;
}

}  // namespace

TEST_CASE("embree oracle: away from edges its depths lie within the tolerance of the device's") {
  // The tolerance's premise (embree_oracle.hpp): at every pixel centre 1/256 px or more from
  // a projected edge, coverage is the same and each boundary's depth differs by at most one
  // step. Held over every pixel of both blocks of a third of the suite.
  verify::PairSuiteOptions options;
  options.count = 168;
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite(options);
  verify::EmbreeOracle oracle;
  long long compared = 0, exact = 0, beyond = 0;
  std::string first;  // the first pixel beyond the tolerance, for the message
  for (const verify::SuitePair& p : suite) {
    const auto [lo, hi] =
        core::pairDepthRange(p.frame.axis, core::boundingBox(p.a), core::boundingBox(p.b));
    const core::OrthoView view(p.frame.axis, p.frame.window, p.frame.width, p.frame.height, lo, hi);
    const raster::PixelRect rect{0, 0, p.frame.width, p.frame.height};
    const verify::EmbreeSamples s = oracle.sample(p.frame, p.a, p.b, rect);
    const DeviceBlock da = renderAlone(p.a, view, rect), db = renderAlone(p.b, view, rect);
    for (std::size_t k = 0; k < s.cases.size(); ++k) {
      if (s.nearEdge[k])
        continue;
      for (int which = 0; which < 2; ++which) {
        const DeviceBlock& d = which == 0 ? da : db;
        const std::optional<DepthInterval>& o = which == 0 ? s.a[k] : s.b[k];
        std::uint32_t dn = 0, df = 0;
        const bool sameCoverage = o.has_value() == (d.covered[k] != 0);
        if (sameCoverage && o) {
          ++compared;
          dn = gap(o->min, d.nearDepth[k]);
          df = gap(o->max, d.farDepth[k]);
          exact += (dn == 0) + (df == 0);
        }
        if (!sameCoverage || dn > verify::kEmbreeDepthTolerance ||
            df > verify::kEmbreeDepthTolerance) {
          if (beyond++ == 0)
            first = p.label + " block " + (which == 0 ? "A" : "B") + " pixel index " +
                    std::to_string(k) + (sameCoverage ? ": depth off by " : ": coverage differs") +
                    (sameCoverage ? std::to_string(std::max(dn, df)) : "");
        }
      }
    }
  }
  INFO(first);
  CHECK(beyond == 0);
  CHECK(compared > 100000);
  // The rounding of the vertices' depths to float must show: were every depth identical, the
  // oracle would merely copy the device's arithmetic.
  CHECK(exact < 2 * compared);
}

TEST_CASE("embree oracle: the generated suite has no unexplained pixel") {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  REQUIRE(suite.size() == 504);
  verify::EmbreeOracle oracle;
  for (const core::MorMode mor : {core::MorMode::Min, core::MorMode::Full}) {
    // With the full MOR and no box test every pixel of every frame carries a device case.
    const bool boxTest = mor == core::MorMode::Min;
    verify::EmbreeCounts total;
    long long interfering = 0;
    std::map<verify::PairConfiguration, verify::EmbreeCounts> byConfiguration;
    for (const verify::SuitePair& p : suite) {
      const core::PairResult r = runPair(p.a, p.b, p.frame, mor, /*contact=*/true, boxTest);
      const verify::EmbreeReport rep = oracle.check(p.frame, p.a, p.b, r);
      INFO(p.label << " (MOR " << core::toString(mor) << ")");
      CHECK(rep.counts.unexplained == 0);
      if (!rep.unexplained.empty()) {
        const verify::PixelDisagreement& d = rep.unexplained[0];
        FAIL_CHECK("pixel (" << d.x << ", " << d.y << "): device case " << d.deviceCase
                             << ", oracle case " << d.oracleCase);
      }
      CHECK(rep.counts.pixels ==
            rep.counts.agree + rep.counts.ties + rep.counts.edges + rep.counts.unexplained);
      CHECK(rep.rays == 4 * rep.counts.pixels);
      total += rep.counts;
      byConfiguration[p.configuration] += rep.counts;
      interfering += r.interferingPixels;
    }
    INFO("MOR " << core::toString(mor));
    CHECK(total.unexplained == 0);
    // The suite exercises the oracle: many interfering pixels, and most pixels agree outright.
    CHECK(interfering > 10000);
    CHECK(100 * total.agree > 99 * total.pixels);
    if (mor == core::MorMode::Full) {
      long long framePixels = 0;
      for (const verify::SuitePair& p : suite)
        framePixels += static_cast<long long>(p.frame.width) * p.frame.height;
      CHECK(total.pixels == framePixels);
    }
  }
}
