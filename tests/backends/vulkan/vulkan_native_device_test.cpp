// The native Vulkan device (vulkan-native) against what the Vulkan specification fixes, not
// against the contract's bits, which a driver's own rasterizer and depth do not promise: the
// start state, stencil ops and which of them a fragment takes, compare functions and masks,
// clears under the scissor and the write masks, facing and culling, read-back orientation, the
// interiors of triangles (samples well away from every edge, so no sub-pixel precision or tie
// rule decides them) and the depth order of well separated surfaces. Expected values are worked
// out by hand, with depths far apart or at 0 and 1 (exact in every conversion). Runs on whatever
// Vulkan driver the loader finds (lavapipe here); without one every case says so and passes.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/backends/device_registry.hpp"
#include "recode/backends/vulkan_native_device.hpp"
#include "recode/raster/state.hpp"

using namespace recode::raster;
using recode::backends::VulkanNativeDevice;
namespace backends = recode::backends;

namespace {

// Whether this machine has a Vulkan driver the device can use; when not, a warning says why
// (once a case) and the case checks nothing.
bool vulkanHere() {
  static const std::string why = [] {
    try {
      VulkanNativeDevice probe(1, 1);
      return std::string();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
  }();
  if (!why.empty())
    WARN("no Vulkan device here, nothing checked: " << why);
  return why.empty();
}

// A rectangle [x0, x1) x [y0, y1) as two counter-clockwise triangles at depth z: edges on pixel
// boundaries, so exactly the pixels inside are covered (every centre half a pixel from an edge).
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

// Every fragment passes both tests and takes `op`; depth neither tested nor written.
void passOp(DepthStencilDevice& dev, StencilOp op, std::uint8_t ref = 0) {
  dev.setDepthFunc(CompareFunc::Always);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::Always, ref, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, op});
}

// The signed distance in pixels of (px, py) from the line a->b, positive on its left.
double edgeDistance(const WindowVertex& a, const WindowVertex& b, double px, double py) {
  const double ex = b.x - a.x;
  const double ey = b.y - a.y;
  return (ex * (py - a.y) - ey * (px - a.x)) / std::hypot(ex, ey);
}

// A pixel centre whose coverage by the counter-clockwise triangle abc no freedom of the APIs can
// change: +1 at least `margin` pixels inside every edge, -1 that far outside one, 0 otherwise.
int sideOf(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, int x, int y,
           double margin) {
  const double px = x + 0.5;
  const double py = y + 0.5;
  const double d[3] = {edgeDistance(a, b, px, py), edgeDistance(b, c, px, py),
                       edgeDistance(c, a, px, py)};
  if (d[0] >= margin && d[1] >= margin && d[2] >= margin)
    return 1;
  if (d[0] <= -margin || d[1] <= -margin || d[2] <= -margin)
    return -1;
  return 0;
}

// Sub-pixel precision is at least 4 bits in Vulkan and GL: a vertex moves at most 1/32 of a pixel
// when snapped, and a sample this far from every edge is decided whatever the driver snaps to.
constexpr double kMargin = 0.125;

// 0.25 times 2^24 - 1, rounded to nearest: a constant plane's 24-bit depth.
constexpr std::uint32_t kQuarter = 4194304;

}  // namespace

TEST_CASE("the native Vulkan device starts at depth 1 and stencil 0, in a 24-bit format",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  VulkanNativeDevice dev(7, 5);
  CHECK(dev.width() == 7);
  CHECK(dev.height() == 5);
  CHECK_FALSE(dev.renderer().empty());
  CHECK((dev.depthStencilFormat() == "D24_UNORM_S8_UINT" ||
         dev.depthStencilFormat() == "D32_SFLOAT_S8_UINT"));
  CHECK(dev.defers());
  CHECK(dev.readDepth({0, 0, 7, 5}) == std::vector<std::uint32_t>(35, kDepthMax));
  CHECK(dev.readStencil({0, 0, 7, 5}) == std::vector<std::uint8_t>(35, 0));
  // Read-backs count their submissions and bytes, as the other Vulkan devices' do.
  CHECK(dev.transfers().submissions >= 2);
  CHECK(dev.transfers().readbackBytes >= 35 * 5);
}

TEST_CASE("the native Vulkan device keeps GL's bottom-left origin and winding", "[vulkan-native]") {
  if (!vulkanHere())
    return;
  VulkanNativeDevice dev(16, 8);
  dev.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  dev.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
  dev.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
  // Counter-clockwise in GL window coordinates (front) in the bottom-left corner: centres with
  // x / 4 + y / 2 < 1 are (0,0), (1,0), (2,0) and (0,1), none near an edge. Clockwise (back)
  // in the top-right corner.
  drawTriangle(dev, {0, 0, 0.5f}, {4, 0, 0.5f}, {0, 2, 0.5f});
  drawTriangle(dev, {16, 8, 0.5f}, {16, 4, 0.5f}, {12, 8, 0.5f});
  const std::vector<std::uint8_t> all = dev.readStencil({0, 0, 16, 8});
  REQUIRE(all.size() == 128);
  CHECK(all[0] == 1);  // row 0, the bottom, comes first
  CHECK(all[1] == 1);
  CHECK(all[2] == 1);
  CHECK(all[3] == 0);
  CHECK(all[16] == 1);      // row 1, column 0
  CHECK(all[127] == 255);   // pixel (15, 7): back-facing, inverted
  CHECK(all[7 * 16] == 0);  // pixel (0, 7): top-left, untouched
  CHECK(all[15] == 0);      // pixel (15, 0): bottom-right, untouched
  // A sub-rectangle starts at its bottom row too.
  CHECK(dev.readStencil({1, 0, 4, 2}) == std::vector<std::uint8_t>{1, 1, 0, 0, 0, 0});
  // Rectangles are clamped to the framebuffer, not to the scissor; empty ones read nothing.
  dev.setScissor({0, 0, 1, 1});
  CHECK(dev.readStencil({-3, -3, 100, 100}).size() == 128);
  CHECK(dev.readDepth({14, 6, 20, 20}).size() == 4);
  CHECK(dev.readStencil({5, 5, 5, 9}).empty());
}

TEST_CASE("the native Vulkan device culls by GL's facing", "[vulkan-native]") {
  if (!vulkanHere())
    return;
  struct Row {
    CullMode mode;
    std::uint8_t front, back;  // stencil after a front and a back rectangle, each incrementing
  };
  const Row rows[] = {{CullMode::None, 1, 1}, {CullMode::Back, 1, 0}, {CullMode::Front, 0, 1}};
  for (const Row& row : rows) {
    INFO("cull " << static_cast<int>(row.mode));
    VulkanNativeDevice dev(4, 2);
    passOp(dev, StencilOp::Incr);
    dev.setCullMode(row.mode);
    drawRect(dev, 0, 0, 2, 2, 0.5f);  // counter-clockwise: front
    const WindowVertex v[4] = {{2, 0, 0.5f}, {2, 2, 0.5f}, {4, 2, 0.5f}, {4, 0, 0.5f}};
    const std::uint32_t i[6] = {0, 1, 2, 0, 2, 3};  // clockwise: back
    dev.drawTriangles(v, i);
    CHECK(dev.readStencil({0, 0, 4, 2}) == std::vector<std::uint8_t>{row.front, row.front, row.back,
                                                                     row.back, row.front, row.front,
                                                                     row.back, row.back});
  }
}

TEST_CASE("the native Vulkan device's stencil ops saturate and wrap as the APIs say",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
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
    VulkanNativeDevice dev(3, 1);
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

TEST_CASE("the native Vulkan device gives stencil fail, depth fail and depth pass their own ops",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  VulkanNativeDevice dev(3, 1);
  dev.clearDepth(0.5);
  dev.clearStencil(10);
  // Column 0: the stencil test fails (ref 10 LESS stored 10 is false). Column 1: the stencil
  // passes (9 < 10), the depth test fails (0.75 LESS 0.5 is false). Column 2: both pass.
  dev.setDepthFunc(CompareFunc::Less);
  dev.setStencilOps(Face::Both, {StencilOp::Zero, StencilOp::Invert, StencilOp::Incr});
  dev.setStencilFunc(CompareFunc::Less, 10, 0xFF);
  drawRect(dev, 0, 0, 1, 1, 0.25f);
  dev.setStencilFunc(CompareFunc::Less, 9, 0xFF);
  drawRect(dev, 1, 0, 2, 1, 0.75f);
  drawRect(dev, 2, 0, 3, 1, 0.25f);
  CHECK(dev.readStencil({0, 0, 3, 1}) == std::vector<std::uint8_t>{0, 245, 11});
  // The stencil's value mask: (ref & 0x0F) EQUAL (stored & 0x0F) holds for stored 0xF5 and ref
  // 0x05 (column 1), not for stored 0x00 or 0x0B.
  dev.setDepthFunc(CompareFunc::Always);
  dev.setStencilFunc(CompareFunc::Equal, 0x05, 0x0F);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Zero});
  drawRect(dev, 0, 0, 3, 1, 0.25f);
  CHECK(dev.readStencil({0, 0, 3, 1}) == std::vector<std::uint8_t>{0, 0, 11});
}

TEST_CASE("the native Vulkan device's depth functions order well separated depths",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  // Columns 0-1 get a quad nearer than the stored 0.5, columns 4-5 a farther one; the stencil
  // records which fragments passed. (An equal depth is left out: the APIs do not promise that a
  // fragment's interpolated 0.5 and a cleared 0.5 convert to the same 24 bits.)
  struct Row {
    CompareFunc func;
    bool passNearer, passFarther;
  };
  const Row rows[] = {
      {CompareFunc::Never, false, false}, {CompareFunc::Less, true, false},
      {CompareFunc::LEqual, true, false}, {CompareFunc::Greater, false, true},
      {CompareFunc::GEqual, false, true}, {CompareFunc::NotEqual, true, true},
      {CompareFunc::Always, true, true},  {CompareFunc::Equal, false, false},
  };
  for (const Row& row : rows) {
    INFO("depth func " << toString(row.func));
    VulkanNativeDevice dev(6, 2);
    dev.clearDepth(0.5);
    dev.setDepthFunc(row.func);
    dev.setDepthWriteMask(false);
    dev.setStencilFunc(CompareFunc::Always, 1, 0xFF);
    dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
    drawRect(dev, 0, 0, 2, 2, 0.25f);
    drawRect(dev, 4, 0, 6, 2, 0.75f);
    const std::uint8_t nearer = row.passNearer ? 1 : 0;
    const std::uint8_t farther = row.passFarther ? 1 : 0;
    CHECK(dev.readStencil({0, 0, 6, 1}) ==
          std::vector<std::uint8_t>{nearer, nearer, 0, 0, farther, farther});
  }
}

TEST_CASE("the native Vulkan device writes depth by its mask, near its plane", "[vulkan-native]") {
  if (!vulkanHere())
    return;
  VulkanNativeDevice dev(4, 4);
  dev.setDepthWriteMask(false);
  drawRect(dev, 0, 0, 4, 4, 0.25f);
  CHECK(dev.readDepth({0, 0, 4, 4}) == std::vector<std::uint32_t>(16, kDepthMax));
  dev.setDepthWriteMask(true);
  drawRect(dev, 0, 0, 4, 4, 0.25f);
  // A constant plane's depth is the driver's conversion of its z: within a step or two of the
  // nearest 24-bit value (float interpolation of equal values, then the conversion).
  for (const std::uint32_t d : dev.readDepth({0, 0, 4, 4})) {
    INFO("depth " << d);
    CHECK(std::abs(static_cast<long long>(d) - static_cast<long long>(kQuarter)) <= 2);
  }
  // z = 0 and z = 1 convert exactly in every format.
  drawRect(dev, 0, 0, 2, 4, 0.0f);
  CHECK(dev.readDepth({0, 0, 2, 1}) == std::vector<std::uint32_t>{0, 0});
}

TEST_CASE("the native Vulkan device's clears honour the scissor and the write masks",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  VulkanNativeDevice dev(4, 2);
  dev.clearStencil(0xF0);
  // A masked clear inside a scissor: s = (0x0F & 0x3C) | (s & ~0x3C) = 0xCC in columns 1-2.
  dev.setScissor({1, 0, 3, 2});
  dev.setStencilWriteMask(0x3C);
  dev.clearStencil(0x0F);
  CHECK(dev.readStencil({0, 0, 4, 1}) == std::vector<std::uint8_t>{0xF0, 0xCC, 0xCC, 0xF0});
  // Write mask 0: nothing changes.
  dev.setStencilWriteMask(0);
  dev.clearStencil(0x00);
  CHECK(dev.readStencil({0, 0, 4, 1}) == std::vector<std::uint8_t>{0xF0, 0xCC, 0xCC, 0xF0});
  // Depth: cleared inside the scissor, and not at all with the depth write mask off; depth
  // outside [0, 1] is clamped, as GL clamps it.
  dev.clearDepth(0.0);
  CHECK(dev.readDepth({0, 0, 4, 1}) == std::vector<std::uint32_t>{kDepthMax, 0, 0, kDepthMax});
  dev.setScissor({0, 0, 2, 2});
  dev.setDepthWriteMask(false);
  dev.clearDepth(1.0);
  CHECK(dev.readDepth({0, 0, 4, 1}) == std::vector<std::uint32_t>{kDepthMax, 0, 0, kDepthMax});
  dev.setDepthWriteMask(true);
  dev.clearDepth(7.0);
  CHECK(dev.readDepth({0, 0, 4, 1}) ==
        std::vector<std::uint32_t>{kDepthMax, kDepthMax, 0, kDepthMax});
  // An empty scissor clears nothing; a draw outside the scissor writes nothing.
  dev.setScissor({3, 3, 3, 3});
  dev.setStencilWriteMask(0xFF);
  dev.clearStencil(0x11);
  passOp(dev, StencilOp::Replace, 0x22);
  drawRect(dev, 0, 0, 4, 2, 0.5f);
  CHECK(dev.readStencil({0, 0, 4, 1}) == std::vector<std::uint8_t>{0xF0, 0xCC, 0xCC, 0xF0});
}

TEST_CASE("the native Vulkan device covers a triangle's interior, however far its vertices lie",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  // A sloped triangle across the frame, and one whose vertices lie thousands of pixels outside
  // it (beyond the viewport: the driver clips it, which may move no interior sample).
  const std::array<std::array<WindowVertex, 3>, 2> triangles = {{
      {{{1.3f, 0.7f, 0.2f}, {37.9f, 5.1f, 0.6f}, {9.2f, 22.6f, 0.9f}}},
      {{{-20000.0f, -3.0f, 0.5f}, {30000.0f, 2.0f, 0.5f}, {10.0f, 24000.0f, 0.5f}}},
  }};
  for (const auto& t : triangles) {
    INFO("triangle from (" << t[0].x << ", " << t[0].y << ")");
    VulkanNativeDevice dev(40, 24);
    passOp(dev, StencilOp::Replace, 1);
    drawTriangle(dev, t[0], t[1], t[2]);
    const std::vector<std::uint8_t> stencil = dev.readStencil({0, 0, 40, 24});
    int decided = 0;
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 40; ++x) {
        const int side = sideOf(t[0], t[1], t[2], x, y, kMargin);
        if (side == 0)
          continue;
        ++decided;
        INFO("pixel (" << x << ", " << y << ")");
        CHECK(stencil[static_cast<std::size_t>(y * 40 + x)] == (side > 0 ? 1 : 0));
      }
    }
    CHECK(decided > 800);
  }
}

TEST_CASE("the native Vulkan device draws every triangle of a draw that has a zero-area one",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  // kit/culling_11's first draw: a back-facing triangle, a front-facing one, a zero-area one.
  // Drawn as a list without indices, lavapipe (Mesa 22.3.6) drew none of them; the device draws
  // indexed, as the GL device does. Every triangle of a draw is the APIs' to rasterize.
  const WindowVertex v[9] = {{-241 / 256.0f, -66 / 256.0f, 0.75f},
                             {2524 / 256.0f, 3581 / 256.0f, 0.75f},
                             {386 / 256.0f, 384 / 256.0f, 0.75f},
                             {-143 / 256.0f, 2359 / 256.0f, 0.25f},
                             {3342 / 256.0f, 260 / 256.0f, 0.25f},
                             {733 / 256.0f, 4142 / 256.0f, 0.25f},
                             {0.5f, 10.5f, 0.5f},
                             {8.5f, 10.5f, 0.5f},
                             {15.5f, 10.5f, 0.5f}};
  const std::uint32_t indices[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  VulkanNativeDevice dev(16, 16);
  dev.setDepthFunc(CompareFunc::Always);
  dev.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
  dev.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::DecrWrap});
  dev.drawTriangles(v, indices);
  const std::vector<std::uint8_t> stencil = dev.readStencil({0, 0, 16, 16});
  int front = 0;
  int back = 0;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      // The back-facing triangle winds clockwise: its vertices reversed wind counter-clockwise.
      const int inFront = sideOf(v[3], v[4], v[5], x, y, kMargin);
      const int inBack = sideOf(v[0], v[2], v[1], x, y, kMargin);
      const std::uint8_t s = stencil[static_cast<std::size_t>(y * 16 + x)];
      if (inFront > 0 && inBack < 0) {
        ++front;
        CHECK(s == 1);
      }
      if (inBack > 0 && inFront < 0) {
        ++back;
        CHECK(s == 255);
      }
    }
  }
  CHECK(front > 40);
  CHECK(back > 0);
}

TEST_CASE("the native Vulkan device keeps the nearer of two well separated surfaces",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  // Two sloped triangles over the same pixels, one between z 0.1 and 0.3, the other between 0.6
  // and 0.9: whichever order they come in, LESS keeps the near one, and the far one's fragments
  // where they overlap fail the depth test.
  const WindowVertex nearT[3] = {{0.4f, 0.3f, 0.1f}, {30.6f, 1.2f, 0.3f}, {2.1f, 19.8f, 0.2f}};
  const WindowVertex farT[3] = {{0.2f, 0.6f, 0.9f}, {31.5f, 0.4f, 0.6f}, {1.2f, 20.5f, 0.75f}};
  for (const bool nearFirst : {true, false}) {
    INFO((nearFirst ? "near first" : "far first"));
    VulkanNativeDevice dev(32, 20);
    dev.setDepthFunc(CompareFunc::Less);
    dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Incr, StencilOp::Replace});
    const auto draw = [&](const WindowVertex* t, std::uint8_t ref) {
      dev.setStencilFunc(CompareFunc::Always, ref, 0xFF);
      drawTriangle(dev, t[0], t[1], t[2]);
    };
    if (nearFirst) {
      draw(nearT, 1);
      draw(farT, 2);
    } else {
      draw(farT, 2);
      draw(nearT, 1);
    }
    const std::vector<std::uint8_t> stencil = dev.readStencil({0, 0, 32, 20});
    const std::vector<std::uint32_t> depth = dev.readDepth({0, 0, 32, 20});
    int both = 0;
    for (int y = 0; y < 20; ++y) {
      for (int x = 0; x < 32; ++x) {
        if (sideOf(nearT[0], nearT[1], nearT[2], x, y, kMargin) <= 0 ||
            sideOf(farT[0], farT[1], farT[2], x, y, kMargin) <= 0)
          continue;
        ++both;
        INFO("pixel (" << x << ", " << y << ")");
        const std::size_t k = static_cast<std::size_t>(y * 32 + x);
        // Near first: the far fragment fails and increments 1 to 2. Far first: the near one
        // passes and replaces 2 with 1.
        CHECK(stencil[k] == (nearFirst ? 2 : 1));
        CHECK(depth[k] < kDepthMax / 2);  // the near surface's depth, below 0.3 (and 0.5)
      }
    }
    CHECK(both > 150);
  }
}

TEST_CASE("native Vulkan devices keep their own buffers in the shared recording",
          "[vulkan-native]") {
  if (!vulkanHere())
    return;
  // Two devices' commands interleaved in one recording, read back later, then at once.
  VulkanNativeDevice a(4, 4);
  VulkanNativeDevice b(6, 3);
  passOp(a, StencilOp::Replace, 7);
  passOp(b, StencilOp::Invert);
  drawRect(a, 0, 0, 4, 4, 0.5f);
  PendingRead<std::uint8_t> laterA = a.readStencilLater({0, 0, 4, 4});
  drawRect(b, 0, 0, 3, 3, 0.5f);
  PendingRead<std::uint8_t> laterB = b.readStencilLater({0, 0, 6, 1});
  passOp(a, StencilOp::Zero);
  drawRect(a, 0, 0, 2, 2, 0.5f);  // after the read: not in laterA
  b.finish();
  CHECK(laterA.take() == std::vector<std::uint8_t>(16, 7));
  CHECK(laterB.take() == std::vector<std::uint8_t>{255, 255, 255, 0, 0, 0});
  CHECK(a.readStencil({0, 0, 4, 1}) == std::vector<std::uint8_t>{0, 0, 7, 7});
}

TEST_CASE("the native Vulkan device refuses what CpuDevice refuses", "[vulkan-native]") {
  if (!vulkanHere())
    return;
  CHECK_THROWS_AS(VulkanNativeDevice(0, 4), std::invalid_argument);
  CHECK_THROWS_AS(VulkanNativeDevice(4, 16385), std::invalid_argument);
  VulkanNativeDevice dev(4, 4);
  const WindowVertex v[3] = {{0, 0, 0.5f}, {4, 0, 0.5f}, {0, 4, 1.5f}};
  const std::uint32_t outOfRange[3] = {0, 1, 3};
  const std::uint32_t i[3] = {0, 1, 2};
  CHECK_THROWS_AS(dev.drawTriangles(v, outOfRange), std::invalid_argument);
  CHECK_THROWS_AS(dev.drawTriangles(v, i), std::invalid_argument);  // z outside [0, 1]
  CHECK_THROWS_AS(dev.clearDepth(std::nan("")), std::invalid_argument);
  // Nothing was drawn by the refused calls.
  CHECK(dev.readStencil({0, 0, 4, 4}) == std::vector<std::uint8_t>(16, 0));
}

TEST_CASE("the registry makes vulkan-native, and does not call it exact", "[vulkan-native]") {
  const backends::DeviceInfo& info = backends::deviceInfo(backends::DeviceKind::VulkanNative);
  CHECK(info.name == "vulkan-native");
  CHECK_FALSE(info.exact);
  CHECK(info.built);
  if (!vulkanHere())
    return;
  const auto device = backends::makeDevice(backends::DeviceKind::VulkanNative, 5, 3);
  CHECK(dynamic_cast<VulkanNativeDevice*>(device.get()) != nullptr);
  CHECK(device->width() == 5);
  CHECK(device->readDepth({0, 0, 5, 3}) == std::vector<std::uint32_t>(15, kDepthMax));
}
