// The tile/block traversal against the naive per-pixel model: random triangles of every
// size and shape (slivers, huge, off-screen, on the 1/256 grid and on pixel centres), random
// scissors and state; the two must agree on every byte of depth and stencil.

#include <catch2/catch.hpp>
#include <map>
#include <optional>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "recode/kit/reference_model.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/traversal.hpp"
#include "recode/raster/triangle_setup.hpp"

using namespace recode::raster;

namespace {

float randomCoordinate(std::mt19937& rng, int extent, int style) {
  std::uniform_real_distribution<double> u(-0.25 * extent, 1.25 * extent);
  const double x = u(rng);
  switch (style) {
    case 0:
      return static_cast<float>(std::floor(x) + 0.5);  // on pixel centres
    case 1:
      return static_cast<float>(std::round(x * 2.0) / 2.0);  // on pixel corners and centres
    default:
      return static_cast<float>(std::round(x * 256.0) / 256.0);
  }
}

std::vector<Command> randomCommands(std::mt19937& rng, int w, int h) {
  std::vector<Command> cmds;
  std::uniform_int_distribution<int> pick(0, 7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  cmds.push_back(cmd::ClearDepth{unit(rng)});
  for (int batch = 0; batch < 6; ++batch) {
    std::uniform_int_distribution<int> sx(0, w), sy(0, h);
    int x0 = sx(rng), x1 = sx(rng), y0 = sy(rng), y1 = sy(rng);
    if (x0 > x1)
      std::swap(x0, x1);
    if (y0 > y1)
      std::swap(y0, y1);
    if (batch % 2 == 0) {
      cmds.push_back(cmd::Scissor{{0, 0, w, h}});
    } else {
      cmds.push_back(cmd::Scissor{{x0, y0, x1 + 1, y1 + 1}});
    }
    cmds.push_back(cmd::DepthFunc{static_cast<CompareFunc>(pick(rng))});
    cmds.push_back(cmd::DepthWriteMask{pick(rng) < 6});
    cmds.push_back(cmd::StencilFunc{static_cast<CompareFunc>(pick(rng)),
                                    static_cast<std::uint8_t>(pick(rng)), 0xFF});
    cmds.push_back(cmd::StencilOpsCmd{Face::Front,
                                      {static_cast<StencilOp>(pick(rng)),
                                       static_cast<StencilOp>(pick(rng)), StencilOp::IncrWrap}});
    cmds.push_back(cmd::StencilOpsCmd{
        Face::Back,
        {static_cast<StencilOp>(pick(rng)), static_cast<StencilOp>(pick(rng)), StencilOp::Incr}});
    cmds.push_back(cmd::Cull{static_cast<CullMode>(pick(rng) % 3)});
    cmd::Draw d;
    const int style = pick(rng) % 3;
    const int n = 3 * (1 + pick(rng) * 4);
    for (int k = 0; k < n; ++k) {
      d.vertices.push_back({randomCoordinate(rng, w, style), randomCoordinate(rng, h, style),
                            static_cast<float>(unit(rng))});
      d.indices.push_back(static_cast<std::uint32_t>(k));
    }
    // Slivers: make some triangles nearly degenerate.
    if (pick(rng) == 0) {
      d.vertices[2].x = d.vertices[0].x + (d.vertices[1].x - d.vertices[0].x) * 0.5f + 1.0f / 256;
      d.vertices[2].y = d.vertices[0].y + (d.vertices[1].y - d.vertices[0].y) * 0.5f;
    }
    cmds.push_back(std::move(d));
  }
  return cmds;
}

}  // namespace

TEST_CASE("tile traversal equals the per-pixel model on random streams", "[traversal]") {
  std::mt19937 rng(12345);
  // The widest spans many 64x64 tiles, where a long sliver's box holds hundreds of blocks and
  // each row of blocks is narrowed to those no edge rejects before any is tested.
  const int sizes[][2] = {{1, 1}, {7, 9}, {64, 64}, {65, 63}, {130, 70}, {200, 17}, {520, 300}};
  int streams = 0;
  for (const auto& s : sizes) {
    for (int trial = 0; trial < 40; ++trial) {
      const int w = s[0], h = s[1];
      const auto cmds = randomCommands(rng, w, h);
      CpuDevice dev(w, h);
      replay(cmds, dev);
      recode::kit::ReferenceModel model(w, h);
      model.run(cmds);
      INFO("size " << w << "x" << h << " trial " << trial);
      int stencilDiff = 0, depthDiff = 0;
      for (std::size_t i = 0; i < model.stencilBuffer().size(); ++i) {
        stencilDiff += dev.stencilBuffer()[i] != model.stencilBuffer()[i];
        depthDiff += dev.depthBuffer()[i] != model.depthBuffer()[i];
      }
      CHECK(stencilDiff == 0);
      CHECK(depthDiff == 0);
      ++streams;
    }
  }
  CHECK(streams == 280);
}

TEST_CASE("traversal rejects and accepts whole tiles and blocks", "[traversal]") {
  // A large triangle in a 512x512 framebuffer: most of its area is accepted as whole tiles,
  // and the blocks crossed by its edges are tested pixel by pixel.
  CpuDevice dev(512, 512);
  const WindowVertex v[3] = {{0, 0, 0.5f}, {512, 0, 0.5f}, {0, 512, 0.5f}};
  const std::uint32_t idx[3] = {0, 1, 2};
  dev.drawTriangles(v, idx);
  const auto& t = dev.counters().traversal;
  CHECK(t.tilesAccepted == 28);  // tiles strictly below the diagonal: 7+6+...+1
  CHECK(t.tilesRejected == 28);  // and strictly above it
  CHECK(t.blocksPartial == 64);  // the 8x8 blocks on the diagonal
  CHECK(dev.counters().fragments == 512u * 511u / 2u);
}

TEST_CASE("a block's mask inside a rectangle is its pixels inside it, pixel by pixel",
          "[raster][traversal]") {
  // Every rectangle with corners from -2 to 21 (empty, inverted and partial ones included)
  // against the blocks at 0, 8 and 16 on both axes: the shortcut for a whole block and the
  // row-copying product against a direct test of each pixel.
  const auto direct = [](int x, int y, const PixelRect& rect) {
    std::uint64_t mask = 0;
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c)
        if (x + c >= rect.x0 && x + c < rect.x1 && y + r >= rect.y0 && y + r < rect.y1)
          mask |= std::uint64_t{1} << (r * 8 + c);
    return mask;
  };
  long long compared = 0, whole = 0;
  for (int x0 = -2; x0 < 20; ++x0)
    for (int x1 = x0 - 1; x1 < 22; ++x1)
      for (int y0 = -2; y0 < 20; ++y0)
        for (int y1 = y0 - 1; y1 < 22; ++y1)
          for (int bx = 0; bx <= 16; bx += 8)
            for (int by = 0; by <= 16; by += 8) {
              const PixelRect rect{x0, y0, x1, y1};
              const std::uint64_t expected = direct(bx, by, rect);
              if (blockMaskInside(bx, by, rect) != expected)
                FAIL("block (" << bx << ", " << by << ") in [" << x0 << ", " << x1 << ") x [" << y0
                               << ", " << y1 << ")");
              ++compared;
              whole += expected == ~std::uint64_t{0};
            }
  CHECK(compared == 915849);
  CHECK(whole > 0);
}

namespace {

// Every block the traversal hands out, in order.
struct BlockList final : BlockSink {
  struct Block {
    int x, y;
    std::uint64_t mask;
  };
  std::vector<Block> blocks;
  void coveredBlock(int x, int y, std::uint64_t mask) override { blocks.push_back({x, y, mask}); }
};

}  // namespace

TEST_CASE("small triangles over block and tile edges: each pixel's own edge test, tile order",
          "[traversal]") {
  // Triangles of a few pixels around the corner where four tiles meet, so that their areas
  // span two or three blocks and often two tiles, under random scissors. Expected: for each
  // pixel of the clip, all three edge functions non-negative at its centre; blocks handed out
  // once each, never empty, tiles row by row and each tile's blocks row by row.
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> centre(52.0, 76.0), offset(-3.0, 3.0);
  std::uniform_int_distribution<int> edge(40, 88);
  long long multiBlock = 0, multiTile = 0, covered = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double cx = centre(rng), cy = centre(rng);
    FixedVertex v[3];
    for (FixedVertex& p : v)
      p = snapVertex({snapToSubpixel(cx + offset(rng)), snapToSubpixel(cy + offset(rng)), 0.5f});
    const std::optional<TriangleCoverage> tri = setupCoverage(v[0], v[1], v[2]);
    if (!tri)
      continue;
    int x0 = edge(rng), x1 = edge(rng), y0 = edge(rng), y1 = edge(rng);
    if (x0 > x1)
      std::swap(x0, x1);
    if (y0 > y1)
      std::swap(y0, y1);
    const PixelRect clip = trial % 3 == 0 ? PixelRect{0, 0, 128, 128} : PixelRect{x0, y0, x1, y1};
    BlockList list;
    traverseTriangle(*tri, clip, list);

    std::map<std::pair<int, int>, std::uint64_t> expected;  // (y, x) of the block -> mask
    const PixelRect area = tri->bounds.intersect(clip);
    for (int py = clip.y0; py < clip.y1; ++py)
      for (int px = clip.x0; px < clip.x1; ++px) {
        const std::int64_t x = pixelCentreFixed(px), y = pixelCentreFixed(py);
        if (tri->edges[0].at(x, y) >= 0 && tri->edges[1].at(x, y) >= 0 &&
            tri->edges[2].at(x, y) >= 0)
          expected[{py / 8 * 8, px / 8 * 8}] |= std::uint64_t{1} << (py % 8 * 8 + px % 8);
      }
    std::map<std::pair<int, int>, std::uint64_t> got;
    const auto orderKey = [](const BlockList::Block& b) {
      return std::make_tuple(b.y / 64, b.x / 64, b.y, b.x);
    };
    for (std::size_t k = 0; k < list.blocks.size(); ++k) {
      const BlockList::Block& b = list.blocks[k];
      REQUIRE(b.mask != 0);
      REQUIRE(got.count({b.y, b.x}) == 0);
      got[{b.y, b.x}] = b.mask;
      if (k > 0)
        REQUIRE(orderKey(list.blocks[k - 1]) < orderKey(b));
    }
    INFO("trial " << trial);
    REQUIRE(got == expected);
    if (!area.empty() && area.width() * area.height() <= 16) {
      multiBlock += area.x0 / 8 != (area.x1 - 1) / 8 || area.y0 / 8 != (area.y1 - 1) / 8;
      multiTile += area.x0 / 64 != (area.x1 - 1) / 64 || area.y0 / 64 != (area.y1 - 1) / 64;
    }
    covered += !got.empty();
  }
  // The cases the small-area path serves were really there.
  CHECK(multiBlock > 2000);
  CHECK(multiTile > 500);
  CHECK(covered > 5000);
}

TEST_CASE("a tile whose corner samples lie on an inclusive edge is accepted whole", "[traversal]") {
  // The triangle (0.5, 0.5) (200.5, 0.5) (0.5, 200.5): its bottom edge (running right) and left
  // edge (running down) are inclusive and pass through the centres of row 0 and column 0, where
  // their edge values are exactly 0; the diagonal is exclusive. A tile is accepted when every
  // edge is >= 0 at all its corner samples, 0 included: the tiles at (0, 0), (64, 0) and (0, 64)
  // (their far corner's centre sum tx + ty + 127 is below 201). Rejected: the six whose near
  // corner's sum tx + ty + 1 reaches 201. The other 7 of the 16 tiles over the bounds are
  // partial. Covered: the pixels with i + j <= 199, 200 * 201 / 2 of them.
  CpuDevice dev(256, 256);
  const WindowVertex v[3] = {{0.5f, 0.5f, 0.5f}, {200.5f, 0.5f, 0.5f}, {0.5f, 200.5f, 0.5f}};
  const std::uint32_t idx[3] = {0, 1, 2};
  dev.drawTriangles(v, idx);
  const auto& t = dev.counters().traversal;
  CHECK(t.tilesAccepted == 3);
  CHECK(t.tilesRejected == 6);
  CHECK(dev.counters().fragments == 200u * 201u / 2u);
}

TEST_CASE("a small area over two blocks visits those two blocks only", "[traversal]") {
  // A large triangle clipped to pixels [6, 16) x [0, 1): 10 pixels, at most kSmallArea, over the
  // blocks at x = 0 and x = 8 (the area ends exactly at the block edge 16). The small-area path
  // tests each of the two blocks once: two partial blocks, no block at x = 16.
  const FixedVertex a{-256 * 100, -256 * 100, 0.5f}, b{256 * 300, -256 * 100, 0.5f},
      c{-256 * 100, 256 * 300, 0.5f};
  const std::optional<TriangleCoverage> tri = setupCoverage(a, b, c);
  REQUIRE(tri);
  BlockList list;
  TraversalStats stats;
  traverseTriangle(*tri, {6, 0, 16, 1}, list, &stats);
  CHECK(stats.blocksPartial == 2);
  CHECK(stats.blocksAccepted == 0);
  REQUIRE(list.blocks.size() == 2);
  CHECK(list.blocks[0].x == 0);
  CHECK(list.blocks[0].mask == 0xC0);  // columns 6 and 7 of row 0
  CHECK(list.blocks[1].x == 8);
  CHECK(list.blocks[1].mask == 0xFF);  // columns 8 to 15
}

TEST_CASE("a clip of one whole block is that block's coverage, with no tile tested",
          "[traversal]") {
  // traversal.hpp: a triangle whose pixels in the clip lie in one block counts one partial
  // block and no tile. The clip [8, 16) x [8, 16) is exactly the block at (8, 8), its top and
  // right edges on the block's (a larger area would go through the tile and block tests: a
  // triangle covering the whole tile would count it accepted).
  const FixedVertex a{-256 * 100, -256 * 100, 0.5f}, b{256 * 300, -256 * 100, 0.5f},
      c{-256 * 100, 256 * 300, 0.5f};
  const std::optional<TriangleCoverage> tri = setupCoverage(a, b, c);
  REQUIRE(tri);
  BlockList list;
  TraversalStats stats;
  traverseTriangle(*tri, {8, 8, 16, 16}, list, &stats);
  CHECK(stats.blocksPartial == 1);
  CHECK(stats.blocksAccepted == 0);
  CHECK(stats.tilesAccepted == 0);
  CHECK(stats.tilesRejected == 0);
  REQUIRE(list.blocks.size() == 1);
  CHECK(list.blocks[0].x == 8);
  CHECK(list.blocks[0].y == 8);
  CHECK(list.blocks[0].mask == ~std::uint64_t{0});
}
