// GlDevice on its own: every piece of state, the read-back orientation, the errors. Expected
// values are worked out by hand from GL's rules (docs/rasterization.md, section 6), with
// constant-depth quads so that no depth rounding is involved. Built once per context platform
// (RECODE_TEST_GL_PLATFORM: OsMesa, or Egl with its framebuffer object), test names alike.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/backends/gl_device.hpp"
#include "recode/raster/state.hpp"

using namespace recode::raster;
using recode::backends::GlDevice;
namespace backends = recode::backends;

#ifndef RECODE_TEST_GL_PLATFORM
#define RECODE_TEST_GL_PLATFORM OsMesa
#endif

namespace {

constexpr backends::GlPlatform kPlatform = backends::GlPlatform::RECODE_TEST_GL_PLATFORM;

// A rectangle [x0, x1) x [y0, y1) drawn as two counter-clockwise triangles at depth z. Edges
// on pixel boundaries, so exactly the pixels inside are covered.
void drawRect(DepthStencilDevice& dev, float x0, float y0, float x1, float y1, float z) {
  const WindowVertex v[4] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  const std::uint32_t i[6] = {0, 1, 2, 0, 2, 3};
  dev.drawTriangles(v, i);
}

void drawTriangle(DepthStencilDevice& dev, WindowVertex a, WindowVertex b, WindowVertex c) {
  const WindowVertex v[3] = {a, b, c};
  const std::uint32_t i[3] = {0, 1, 2};
  dev.drawTriangles(v, i);
}

std::uint8_t stencilAt(const DepthStencilDevice& dev, int x, int y) {
  return dev.readStencil({x, y, x + 1, y + 1}).at(0);
}

std::uint32_t depthAt(const DepthStencilDevice& dev, int x, int y) {
  return dev.readDepth({x, y, x + 1, y + 1}).at(0);
}

// Stencil op applied to every fragment that passes both tests; depth test off.
void passOp(DepthStencilDevice& dev, StencilOp op, std::uint8_t ref = 0) {
  dev.setDepthFunc(CompareFunc::Always);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::Always, ref, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, op});
}

// 0.25, 0.5 and 0.75 times 2^24 - 1, rounded to nearest (0.5 * (2^24 - 1) ends in .5 and
// rounds to even): the 24-bit depths of those constant planes.
constexpr std::uint32_t kQuarter = 4194304;
constexpr std::uint32_t kHalf = 8388608;
constexpr std::uint32_t kThreeQuarters = 12582911;

}  // namespace

TEST_CASE("GL device starts cleared to depth 1 and stencil 0", "[gl]") {
  GlDevice dev(7, 5, kPlatform);
  CHECK(dev.width() == 7);
  CHECK(dev.height() == 5);
  CHECK(dev.renderer().find("llvmpipe") != std::string::npos);
  const auto depth = dev.readDepth({0, 0, 7, 5});
  const auto stencil = dev.readStencil({0, 0, 7, 5});
  REQUIRE(depth.size() == 35);
  REQUIRE(stencil.size() == 35);
  for (std::size_t i = 0; i < depth.size(); ++i) {
    CHECK(depth[i] == kDepthMax);
    CHECK(stencil[i] == 0);
  }
}

TEST_CASE("GL read-backs are row-major from the bottom row up", "[gl]") {
  GlDevice dev(16, 8, kPlatform);
  passOp(dev, StencilOp::Replace, 1);
  // A triangle in the bottom-left corner: pixel centres (i + 0.5, j + 0.5) with
  // x / 4 + y / 2 < 1 are (0,0), (1,0), (2,0) and (0,1); none lies on an edge.
  drawTriangle(dev, {0, 0, 0.5f}, {4, 0, 0.5f}, {0, 2, 0.5f});
  const auto all = dev.readStencil({0, 0, 16, 8});
  REQUIRE(all.size() == 128);
  std::vector<std::uint8_t> expected(128, 0);
  expected[0] = expected[1] = expected[2] = 1;  // row 0 (the bottom) comes first
  expected[16] = 1;                             // row 1, column 0
  CHECK(all == expected);

  // A sub-rectangle keeps the order: rows y = 0, 1 of columns 1..3.
  CHECK(dev.readStencil({1, 0, 4, 2}) == std::vector<std::uint8_t>{1, 1, 0, 0, 0, 0});
  // Rectangles are clamped to the framebuffer (not to the scissor); empty ones read nothing.
  dev.setScissor({0, 0, 1, 1});
  CHECK(dev.readStencil({-3, -3, 100, 100}).size() == 128);
  CHECK(dev.readDepth({14, 6, 20, 20}).size() == 4);
  CHECK(dev.readStencil({5, 5, 5, 9}).empty());
  CHECK(dev.readDepth({9, 9, 3, 3}).empty());
  // passOp turned depth writes off: the triangle left the depth at 1.0.
  CHECK(depthAt(dev, 0, 0) == kDepthMax);
}

TEST_CASE("GL depth functions compare incoming with stored depth", "[gl]") {
  // Columns 0-1 get a quad nearer than the stored 0.5, columns 2-3 an equal one, columns 4-5
  // a farther one. The stencil records which fragments passed, the depth what was written.
  struct Row {
    CompareFunc func;
    bool passNearer, passEqual, passFarther;
  };
  const Row rows[] = {
      {CompareFunc::Never, false, false, false},  {CompareFunc::Less, true, false, false},
      {CompareFunc::Equal, false, true, false},   {CompareFunc::LEqual, true, true, false},
      {CompareFunc::Greater, false, false, true}, {CompareFunc::NotEqual, true, false, true},
      {CompareFunc::GEqual, false, true, true},   {CompareFunc::Always, true, true, true},
  };
  for (const Row& row : rows) {
    INFO("depth func " << toString(row.func));
    GlDevice dev(6, 2, kPlatform);
    dev.clearDepth(0.5);
    dev.setDepthFunc(row.func);
    dev.setStencilFunc(CompareFunc::Always, 1, 0xFF);
    dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
    drawRect(dev, 0, 0, 2, 2, 0.25f);
    drawRect(dev, 2, 0, 4, 2, 0.5f);
    drawRect(dev, 4, 0, 6, 2, 0.75f);
    const bool pass[3] = {row.passNearer, row.passEqual, row.passFarther};
    const std::uint32_t written[3] = {kQuarter, kHalf, kThreeQuarters};
    for (int band = 0; band < 3; ++band) {
      for (int x = 2 * band; x < 2 * band + 2; ++x) {
        for (int y = 0; y < 2; ++y) {
          CHECK(stencilAt(dev, x, y) == (pass[band] ? 1 : 0));
          CHECK(depthAt(dev, x, y) == (pass[band] ? written[band] : kHalf));
        }
      }
    }
  }
}

TEST_CASE("GL depth write mask keeps the depth of passing fragments", "[gl]") {
  GlDevice dev(4, 4, kPlatform);
  dev.setDepthFunc(CompareFunc::Less);
  dev.setDepthWriteMask(false);
  passOp(dev, StencilOp::Replace, 3);
  dev.setDepthFunc(CompareFunc::Less);  // passOp switched the test off; the mask stays off
  drawRect(dev, 0, 0, 4, 4, 0.25f);
  CHECK(stencilAt(dev, 1, 1) == 3);
  CHECK(depthAt(dev, 1, 1) == kDepthMax);
  dev.setDepthWriteMask(true);
  drawRect(dev, 0, 0, 4, 4, 0.25f);
  CHECK(depthAt(dev, 1, 1) == kQuarter);
}

TEST_CASE("GL stencil ops, saturating and wrapping", "[gl]") {
  struct Row {
    StencilOp op;
    std::uint8_t from0, from255, from5A;  // results from stored 0, 255 and 0x5A (ref 0x33)
  };
  const Row rows[] = {
      {StencilOp::Keep, 0, 255, 0x5A},        {StencilOp::Zero, 0, 0, 0},
      {StencilOp::Replace, 0x33, 0x33, 0x33}, {StencilOp::Incr, 1, 255, 0x5B},
      {StencilOp::IncrWrap, 1, 0, 0x5B},      {StencilOp::Decr, 0, 254, 0x59},
      {StencilOp::DecrWrap, 255, 254, 0x59},  {StencilOp::Invert, 255, 0, 0xA5},
  };
  for (const Row& row : rows) {
    INFO("stencil op " << toString(row.op));
    GlDevice dev(3, 1, kPlatform);
    // Stored values per column: 0, 255, 0x5A.
    dev.setScissor({1, 0, 2, 1});
    dev.clearStencil(255);
    dev.setScissor({2, 0, 3, 1});
    dev.clearStencil(0x5A);
    dev.setScissor({0, 0, 3, 1});
    passOp(dev, row.op, 0x33);
    drawRect(dev, 0, 0, 3, 1, 0.5f);
    CHECK(dev.readStencil({0, 0, 3, 1}) ==
          std::vector<std::uint8_t>{row.from0, row.from255, row.from5A});
  }
}

TEST_CASE("GL stencil fail, depth fail and depth pass take their own ops", "[gl]") {
  GlDevice dev(3, 1, kPlatform);
  dev.clearDepth(0.5);
  dev.clearStencil(10);
  // Column 0: the stencil test fails (ref 10 LESS stored 10 is false). Column 1: the stencil
  // passes (ref 9 < 10), the depth test fails (0.75 LESS 0.5 is false). Column 2: both pass.
  dev.setDepthFunc(CompareFunc::Less);
  dev.setStencilOps(Face::Both, {StencilOp::Zero, StencilOp::Invert, StencilOp::Incr});
  dev.setStencilFunc(CompareFunc::Less, 10, 0xFF);
  drawRect(dev, 0, 0, 1, 1, 0.25f);
  dev.setStencilFunc(CompareFunc::Less, 9, 0xFF);
  drawRect(dev, 1, 0, 2, 1, 0.75f);
  drawRect(dev, 2, 0, 3, 1, 0.25f);
  CHECK(dev.readStencil({0, 0, 3, 1}) == std::vector<std::uint8_t>{0, 245, 11});
  CHECK(dev.readDepth({0, 0, 3, 1}) == std::vector<std::uint32_t>{kHalf, kHalf, kQuarter});
}

TEST_CASE("GL stencil value mask and write mask", "[gl]") {
  GlDevice dev(2, 1, kPlatform);
  dev.setScissor({0, 0, 1, 1});
  dev.clearStencil(0xAF);
  dev.setScissor({1, 0, 2, 1});
  dev.clearStencil(0xA0);
  dev.setScissor({0, 0, 2, 1});
  // (0x0F & 0x0F) EQUAL (s & 0x0F): passes on 0xAF only; passing pixels are inverted under
  // the write mask 0xF0: (~0xAF & 0xF0) | (0xAF & 0x0F) = 0x5F.
  dev.setDepthFunc(CompareFunc::Always);
  dev.setStencilFunc(CompareFunc::Equal, 0x0F, 0x0F);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
  dev.setStencilWriteMask(0xF0);
  drawRect(dev, 0, 0, 2, 1, 0.5f);
  CHECK(dev.readStencil({0, 0, 2, 1}) == std::vector<std::uint8_t>{0x5F, 0xA0});
}

TEST_CASE("GL per-face stencil ops and culling of either winding", "[gl]") {
  // Left square counter-clockwise (front), right square clockwise (back).
  const auto drawBoth = [](GlDevice& dev) {
    drawRect(dev, 0, 0, 2, 2, 0.5f);
    const WindowVertex v[4] = {{2, 0, 0.5f}, {4, 0, 0.5f}, {4, 2, 0.5f}, {2, 2, 0.5f}};
    const std::uint32_t cw[6] = {0, 2, 1, 0, 3, 2};
    dev.drawTriangles(v, cw);
  };
  struct Row {
    CullMode mode;
    std::uint8_t front, back;
  };
  const Row rows[] = {
      {CullMode::None, 1, 0xFF}, {CullMode::Front, 0, 0xFF}, {CullMode::Back, 1, 0}};
  for (const Row& row : rows) {
    INFO("cull " << toString(row.mode));
    GlDevice dev(4, 2, kPlatform);
    passOp(dev, StencilOp::Keep);
    dev.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr});
    dev.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
    dev.setCullMode(row.mode);
    drawBoth(dev);
    for (int y = 0; y < 2; ++y) {
      CHECK(stencilAt(dev, 0, y) == row.front);
      CHECK(stencilAt(dev, 1, y) == row.front);
      CHECK(stencilAt(dev, 2, y) == row.back);
      CHECK(stencilAt(dev, 3, y) == row.back);
    }
  }
}

TEST_CASE("GL scissor limits draws and clears and is clamped to the framebuffer", "[gl]") {
  GlDevice dev(8, 8, kPlatform);
  dev.setScissor({2, 1, 5, 3});
  dev.clearStencil(7);
  dev.clearDepth(0.0);
  passOp(dev, StencilOp::IncrWrap);
  drawRect(dev, -10, -10, 20, 20, 0.5f);
  int inside = 0;
  const auto stencil = dev.readStencil({0, 0, 8, 8});
  const auto depth = dev.readDepth({0, 0, 8, 8});
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const bool in = x >= 2 && x < 5 && y >= 1 && y < 3;
      inside += in;
      CHECK(stencil[static_cast<std::size_t>(y * 8 + x)] == (in ? 8 : 0));
      CHECK(depth[static_cast<std::size_t>(y * 8 + x)] == (in ? 0u : kDepthMax));
    }
  }
  CHECK(inside == 6);

  // Partly outside: clamped to [0, 8) x [6, 8). Wholly outside: nothing at all.
  dev.setScissor({-5, 6, 100, 100});
  drawRect(dev, 0, 0, 8, 8, 0.5f);
  CHECK(stencilAt(dev, 0, 6) == 1);
  CHECK(stencilAt(dev, 7, 7) == 1);
  CHECK(stencilAt(dev, 0, 5) == 0);
  dev.setScissor({20, 20, 30, 30});
  drawRect(dev, 0, 0, 8, 8, 0.5f);
  dev.clearStencil(99);
  CHECK(stencilAt(dev, 0, 6) == 1);
  CHECK(stencilAt(dev, 3, 2) == 8);
}

TEST_CASE("GL clears honour the write masks", "[gl]") {
  GlDevice dev(4, 4, kPlatform);
  dev.clearStencil(0x50);
  dev.setStencilWriteMask(0x0F);
  dev.clearStencil(0xFF);
  CHECK(stencilAt(dev, 2, 2) == 0x5F);
  dev.setDepthWriteMask(false);
  dev.clearDepth(0.0);
  CHECK(depthAt(dev, 2, 2) == kDepthMax);
  dev.setDepthWriteMask(true);
  dev.clearDepth(0.25);
  CHECK(depthAt(dev, 2, 2) == kQuarter);
  // GL clamps clear values to [0, 1], as the reference's quantisation does.
  dev.clearDepth(7.0);
  CHECK(depthAt(dev, 1, 1) == kDepthMax);
  dev.clearDepth(-1.0);
  CHECK(depthAt(dev, 1, 1) == 0u);
}

TEST_CASE("GL device snaps vertices to the 1/256 grid itself", "[gl]") {
  // The fill_square example of docs/rasterization.md section 4 with every corner 0.001 pixel
  // off the grid: 0.001 * 256 = 0.256 rounds to 0, so the square is the one with corners
  // on pixel centres 2.5 and 6.5, covering pixels 2..5 in each direction, 16 in all.
  GlDevice dev(10, 10, kPlatform);
  passOp(dev, StencilOp::IncrWrap);
  const float lo = 2.5f + 0.001f, hi = 6.5f + 0.001f;
  const WindowVertex v[4] = {{lo, lo, 0.5f}, {hi, lo, 0.5f}, {hi, hi, 0.5f}, {lo, hi, 0.5f}};
  const std::uint32_t i[6] = {0, 1, 2, 0, 2, 3};
  dev.drawTriangles(v, i);
  const auto stencil = dev.readStencil({0, 0, 10, 10});
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool in = x >= 2 && x <= 5 && y >= 2 && y <= 5;
      CHECK(stencil[static_cast<std::size_t>(y * 10 + x)] == (in ? 1 : 0));
    }
  }
}

TEST_CASE("GL device rejects what the CPU device rejects", "[gl][errors]") {
  CHECK_THROWS_AS(GlDevice(0, 4, kPlatform), std::invalid_argument);
  CHECK_THROWS_AS(GlDevice(4, -1, kPlatform), std::invalid_argument);
  CHECK_THROWS_AS(GlDevice(kMaxFramebufferSize + 1, 1, kPlatform), std::invalid_argument);

  GlDevice dev(4, 4, kPlatform);
  passOp(dev, StencilOp::IncrWrap);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const WindowVertex good[3] = {{0, 0, 0.5f}, {4, 0, 0.5f}, {0, 4, 0.5f}};
  const std::uint32_t four[4] = {0, 1, 2, 0};
  const std::uint32_t outOfRange[3] = {0, 1, 3};
  CHECK_THROWS_AS(dev.drawTriangles(good, four), std::invalid_argument);
  CHECK_THROWS_AS(dev.drawTriangles(good, outOfRange), std::invalid_argument);
  const std::uint32_t tri[3] = {0, 1, 2};
  const WindowVertex bad[][3] = {
      {{0, 0, 0.5f}, {4, 0, 0.5f}, {nan, 4, 0.5f}},
      {{0, 0, 0.5f}, {4, 0, 0.5f}, {0, 40000, 0.5f}},
      {{0, 0, 1.5f}, {4, 0, 0.5f}, {0, 4, 0.5f}},
      {{0, 0, -0.1f}, {4, 0, 0.5f}, {0, 4, 0.5f}},
      {{0, 0, 0.5f}, {-std::numeric_limits<float>::infinity(), 0, 0.5f}, {0, 4, 0.5f}},
  };
  for (const auto& vertices : bad)
    CHECK_THROWS_AS(dev.drawTriangles(vertices, tri), std::invalid_argument);
  CHECK_THROWS_AS(dev.clearDepth(std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(dev.clearDepth(HUGE_VAL), std::invalid_argument);
  // A rejected draw changed nothing, and the message names the problem.
  for (std::uint8_t s : dev.readStencil({0, 0, 4, 4}))
    CHECK(s == 0);
  try {
    dev.drawTriangles(bad[2], tri);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("depth outside [0, 1]") != std::string::npos);
  }
  // An unreferenced bad vertex is not an error, as on the CPU device.
  const WindowVertex extra[4] = {{0, 0, 0.5f}, {4, 0, 0.5f}, {0, 4, 0.5f}, {nan, nan, 9.0f}};
  dev.drawTriangles(extra, tri);
  CHECK(stencilAt(dev, 0, 0) == 1);
}

TEST_CASE("several GL devices live side by side, each with its own buffers and state", "[gl]") {
  GlDevice a(8, 8, kPlatform);
  GlDevice b(5, 3, kPlatform);
  passOp(a, StencilOp::Replace, 4);
  b.setStencilFunc(CompareFunc::Always, 9, 0xFF);
  b.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
  b.setDepthFunc(CompareFunc::Less);
  drawRect(a, 0, 0, 2, 2, 0.5f);
  drawRect(b, 0, 0, 5, 3, 0.25f);
  drawRect(a, 6, 6, 8, 8, 0.75f);
  CHECK(stencilAt(a, 1, 1) == 4);
  CHECK(stencilAt(a, 7, 7) == 4);
  CHECK(stencilAt(a, 4, 4) == 0);
  CHECK(depthAt(a, 1, 1) == kDepthMax);  // a's depth mask is off, b's is on
  CHECK(b.readStencil({0, 0, 5, 3}) == std::vector<std::uint8_t>(15, 9));
  CHECK(depthAt(b, 4, 2) == kQuarter);
  {
    GlDevice c(2, 2, kPlatform);  // created and destroyed between uses of a and b
    drawRect(c, 0, 0, 2, 2, 0.5f);
    CHECK(depthAt(c, 0, 0) == kHalf);
  }
  drawRect(a, 3, 3, 4, 4, 0.5f);
  CHECK(stencilAt(a, 3, 3) == 4);
  CHECK(stencilAt(b, 0, 0) == 9);
}
