// Depth quantisation at its boundaries, and the depth plane through snapped vertices.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

#include "raster_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_setup.hpp"

using namespace recode::raster;

TEST_CASE("quantizeDepth at 0, 1, exact steps and half-LSB boundaries", "[depth]") {
  const double D = 16777215.0;
  CHECK(quantizeDepth(0.0) == 0u);
  CHECK(quantizeDepth(1.0) == 16777215u);
  CHECK(quantizeDepth(-0.25) == 0u);
  CHECK(quantizeDepth(1.5) == 16777215u);
  CHECK(quantizeDepth(std::numeric_limits<double>::quiet_NaN()) == 0u);
  CHECK(quantizeDepth(1.0 / D) == 1u);
  CHECK(quantizeDepth(0.5) == 8388608u);  // 0.5 * D = 8388607.5, a tie: to even
  for (std::uint32_t k : {0u, 1u, 2u, 1000u, 8388607u, 8388608u, 16777213u, 16777214u}) {
    INFO("k = " << k);
    CHECK(quantizeDepth(k / D) == k);
    // A tenth of an LSB either side of the half-way point between k and k + 1.
    CHECK(quantizeDepth((k + 0.4) / D) == k);
    CHECK(quantizeDepth((k + 0.6) / D) == k + 1);
  }
  // Exact ties (k + 0.5 representable as z * D): round half to even. 0.5 is such a z since
  // 0.5 * D = 8388607.5 exactly; 0.25 * D = 4194303.75 is not a tie.
  CHECK(quantizeDepth(0.25) == 4194304u);
  CHECK(quantizeDepth(0.75) == 12582911u);  // 12582911.25
}

TEST_CASE("constant-depth triangles store the quantised vertex depth", "[depth]") {
  for (const float z : {0.0f, 1.0f, 0.5f, 0.123456789f, 1e-7f, 0.99999994f}) {
    CpuDevice dev(8, 8);
    dev.setDepthFunc(CompareFunc::Always);
    recode::test::drawTriangle(dev, {0.0f, 0.0f, z}, {8.0f, 0.0f, z}, {0.0f, 8.0f, z});
    INFO("z = " << z);
    CHECK(dev.depthBuffer()[0] == quantizeDepth(z));
  }
}

TEST_CASE("the depth plane is evaluated at pixel centres from the first vertex", "[depth]") {
  // z = x / 64 over a 64-pixel ramp: at pixel centre x = i + 0.5 the plane gives exactly
  // (i + 0.5) / 64 (all values are dyadic, so every operation is exact).
  CpuDevice dev(64, 4);
  dev.setDepthFunc(CompareFunc::Always);
  recode::test::drawTriangle(dev, {0.0f, 0.0f, 0.0f}, {64.0f, 0.0f, 1.0f}, {0.0f, 16.0f, 0.0f});
  recode::test::drawTriangle(dev, {64.0f, 0.0f, 1.0f}, {64.0f, 16.0f, 1.0f}, {0.0f, 16.0f, 0.0f});
  for (int i = 0; i < 64; ++i) {
    const double z = (i + 0.5) / 64.0;
    const auto expected = static_cast<std::uint32_t>(std::nearbyint(z * 16777215.0));
    INFO("pixel " << i);
    CHECK(dev.depthBuffer()[static_cast<std::size_t>(i)] == expected);
    CHECK(dev.depthBuffer()[static_cast<std::size_t>(64 * 3 + i)] == expected);
  }
  // A vertex on a pixel centre where both of its edges are inclusive (bottom and left): the
  // first vertex's depth is reproduced exactly there.
  CpuDevice dev2(16, 16);
  dev2.setDepthFunc(CompareFunc::Always);
  const float z0 = 0.3f;
  recode::test::drawTriangle(dev2, {4.5f, 4.5f, z0}, {14.5f, 4.5f, 0.9f}, {6.0f, 15.0f, 0.1f});
  CHECK(dev2.depthBuffer()[4 * 16 + 4] == quantizeDepth(z0));
}

TEST_CASE("depth test LESS keeps the nearer of two overlapping triangles", "[depth]") {
  CpuDevice dev(16, 16);
  dev.clearDepth(1.0);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
  dev.setStencilFunc(CompareFunc::Always, 1, 0xFF);
  recode::test::drawTriangle(dev, {0, 0, 0.25f}, {16, 0, 0.25f}, {0, 16, 0.25f});
  dev.setStencilFunc(CompareFunc::Always, 2, 0xFF);
  recode::test::drawTriangle(dev, {0, 0, 0.75f}, {16, 0, 0.75f}, {0, 16, 0.75f});
  CHECK(dev.stencilBuffer()[0] == 1);
  CHECK(dev.depthBuffer()[0] == quantizeDepth(0.25f));
  dev.setStencilFunc(CompareFunc::Always, 3, 0xFF);
  recode::test::drawTriangle(dev, {0, 0, 0.125f}, {16, 0, 0.125f}, {0, 16, 0.125f});
  CHECK(dev.stencilBuffer()[0] == 3);
  CHECK(dev.depthBuffer()[0] == quantizeDepth(0.125f));
}

TEST_CASE("stored depth equals DepthPlane::at at every covered sample", "[depth]") {
  // The device computes depth per 8x8 block from column and row terms; the plane's own
  // per-sample formula must give the same bits everywhere.
  const FixedVertex v0{snapToFixed(3.3f), snapToFixed(1.7f), 0.91f};
  const FixedVertex v1{snapToFixed(70.1f), snapToFixed(20.2f), 0.13f};
  const FixedVertex v2{snapToFixed(12.6f), snapToFixed(66.9f), 0.47f};
  const auto tri = setupTriangle(v0, v1, v2);
  REQUIRE(tri.has_value());
  CpuDevice dev(80, 80);
  dev.setDepthFunc(CompareFunc::Always);
  recode::test::drawTriangle(dev, {3.3f, 1.7f, 0.91f}, {70.1f, 20.2f, 0.13f},
                             {12.6f, 66.9f, 0.47f});
  int compared = 0;
  for (int y = 0; y < 80; ++y) {
    for (int x = 0; x < 80; ++x) {
      const std::uint32_t d = dev.depthBuffer()[static_cast<std::size_t>(y * 80 + x)];
      if (d == kDepthMax)
        continue;  // not covered (no sample of this plane reaches 1.0)
      REQUIRE(d == quantizeDepth(tri->depth.at(pixelCentreFixed(x), pixelCentreFixed(y))));
      ++compared;
    }
  }
  CHECK(compared > 1500);
}

TEST_CASE("setupTriangleInto a reused setup gives setupTriangle's every field", "[depth]") {
  // The pipeline sets each triangle of a draw up into one TriangleSetup (setupTriangleInto);
  // whatever the last triangle left there, every field must be this triangle's. Random
  // triangles of both facings, slivers and zero-area ones, with the same setup reused.
  std::mt19937 rng(2611);
  std::uniform_int_distribution<std::int64_t> coordinate(-40 * kSubpixelOne, 40 * kSubpixelOne);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  TriangleSetup reused;
  int checked = 0, degenerate = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    FixedVertex v[3];
    for (FixedVertex& p : v)
      p = {coordinate(rng), coordinate(rng), depth(rng)};
    if (trial % 10 == 0)
      v[2] = {v[0].x + 2 * (v[1].x - v[0].x), v[0].y + 2 * (v[1].y - v[0].y), v[2].z};  // collinear
    const std::optional<TriangleSetup> fresh = setupTriangle(v[0], v[1], v[2]);
    const bool made = setupTriangleInto(v[0], v[1], v[2], reused);
    REQUIRE(made == fresh.has_value());
    if (!made) {
      ++degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      CHECK(reused.edges[k].a == fresh->edges[k].a);
      CHECK(reused.edges[k].b == fresh->edges[k].b);
      CHECK(reused.edges[k].c == fresh->edges[k].c);
    }
    CHECK(reused.frontFacing == fresh->frontFacing);
    CHECK(reused.bounds == fresh->bounds);
    CHECK(reused.depth.x0 == fresh->depth.x0);
    CHECK(reused.depth.y0 == fresh->depth.y0);
    CHECK(std::memcmp(&reused.depth.z0, &fresh->depth.z0, sizeof(double)) == 0);
    CHECK(std::memcmp(&reused.depth.dzdx, &fresh->depth.dzdx, sizeof(double)) == 0);
    CHECK(std::memcmp(&reused.depth.dzdy, &fresh->depth.dzdy, sizeof(double)) == 0);
    ++checked;
  }
  CHECK(checked > 15000);
  CHECK(degenerate >= 2000);
}

TEST_CASE("setupCoverage is setupTriangle's coverage half and nullopt exactly for zero area",
          "[depth]") {
  // The smallest areas either side of zero: twice the area in fixed point is exactly 1 for
  // (0,0) (1,0) (0,1) (counter-clockwise, front-facing) and -1 the other way round; both are
  // triangles. Collinear or coincident vertices (twice the area 0) are not.
  const FixedVertex o{0, 0, 0.5f}, x{1, 0, 0.5f}, y{0, 1, 0.5f};
  const std::optional<TriangleCoverage> ccw = setupCoverage(o, x, y);
  REQUIRE(ccw);
  CHECK(ccw->frontFacing);
  const std::optional<TriangleCoverage> cw = setupCoverage(o, y, x);
  REQUIRE(cw);
  CHECK_FALSE(cw->frontFacing);
  CHECK_FALSE(setupCoverage(o, x, FixedVertex{2, 0, 0.5f}));
  CHECK_FALSE(setupCoverage(o, o, y));
  // Random small triangles (areas near zero often): the same answer, edges, facing and bounds
  // as setupTriangle.
  std::mt19937 rng(1129);
  std::uniform_int_distribution<std::int64_t> coordinate(-3, 3);
  int made = 0, zero = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    FixedVertex v[3];
    for (FixedVertex& p : v)
      p = {coordinate(rng) * 300, coordinate(rng) * 300 + coordinate(rng), 0.25f};
    const std::optional<TriangleSetup> full = setupTriangle(v[0], v[1], v[2]);
    const std::optional<TriangleCoverage> coverage = setupCoverage(v[0], v[1], v[2]);
    REQUIRE(coverage.has_value() == full.has_value());
    if (!coverage) {
      ++zero;
      continue;
    }
    ++made;
    CHECK(coverage->frontFacing == full->frontFacing);
    CHECK(coverage->bounds == full->bounds);
    for (int k = 0; k < 3; ++k) {
      CHECK(coverage->edges[k].a == full->edges[k].a);
      CHECK(coverage->edges[k].b == full->edges[k].b);
      CHECK(coverage->edges[k].c == full->edges[k].c);
    }
  }
  CHECK(made > 1000);
  CHECK(zero > 50);
}
