#include "recode/raster/traversal.hpp"

#include <algorithm>
#include <limits>

#include "recode/raster/block_coverage.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/invariants.hpp"

namespace recode::raster {

namespace {

enum class RegionTest { Reject, Accept, Partial };

// Classifies the size x size pixel square at (px, py) against the three edges from the
// values of each edge function at the square's extreme pixel centres.
RegionTest testRegion(const TriangleCoverage& tri, int px, int py, int size) {
  const std::int64_t x = pixelCentreFixed(px);
  const std::int64_t y = pixelCentreFixed(py);
  const std::int64_t span = static_cast<std::int64_t>(size - 1) * kSubpixelOne;
  bool allInside = true;
  for (const EdgeFunction& e : tri.edges) {
    const std::int64_t base = e.at(x, y);
    const std::int64_t sx = e.a * span, sy = e.b * span;
    const std::int64_t maxE = base + std::max<std::int64_t>(sx, 0) + std::max<std::int64_t>(sy, 0);
    const std::int64_t minE = base + std::min<std::int64_t>(sx, 0) + std::min<std::int64_t>(sy, 0);
    if (maxE < 0)
      return RegionTest::Reject;
    if (minE < 0)
      allInside = false;
  }
  return allInside ? RegionTest::Accept : RegionTest::Partial;
}

// The blocks of one row of blocks (bottom pixel row py) that testRegion would not reject: x
// positions bx with lo <= bx <= hi. Edge k's largest value over the block at bx is
// a (pixelCentreFixed(bx) + max(span, 0)) + b (pixelCentreFixed(py) + max(span, 0)) + c up to
// the sign of each term, linear in bx with slope 256 a, so each edge keeps a half-line of bx
// and the three meet in an interval: the same integers testRegion compares with 0, solved for
// bx exactly. A long sliver's bounding box holds hundreds of blocks of which a few dozen are
// not rejected; only those are visited.
struct BlockSpan {
  std::int64_t lo, hi;
};
BlockSpan unrejectedBlocks(const TriangleCoverage& tri, int py) {
  const std::int64_t span = static_cast<std::int64_t>(kBlockSize - 1) * kSubpixelOne;
  const std::int64_t y = pixelCentreFixed(py);
  BlockSpan keep{std::numeric_limits<std::int64_t>::min(),
                 std::numeric_limits<std::int64_t>::max()};
  for (const EdgeFunction& e : tri.edges) {
    // maxE(bx) = slope * bx + rest, with pixelCentreFixed(bx) = 256 bx + 128.
    const std::int64_t slope = e.a * kSubpixelOne;
    const std::int64_t rest = e.a * (kSubpixelOne / 2) + e.b * y + e.c +
                              std::max<std::int64_t>(e.a * span, 0) +
                              std::max<std::int64_t>(e.b * span, 0);
    if (slope > 0)  // bx >= -rest / slope, rounded up
      keep.lo = std::max(keep.lo, -floorDiv(rest, slope));
    else if (slope < 0)  // bx <= rest / -slope, rounded down
      keep.hi = std::min(keep.hi, floorDiv(rest, -slope));
    else if (rest < 0)
      return {1, 0};  // this edge rejects the whole row (any lo > hi keeps nothing)
  }
  return keep;
}

// Per-pixel edge evaluation of the pixels of one block that lie inside `clip` (the rest would
// be masked off by the caller anyway), from the exact integer edge values at the block's first
// pixel. A sub-pixel triangle's clipped area is a pixel or two: the scalar loop visits just
// those. A larger area goes to the SIMD test, a row of 8 pixels at a time; both give the same
// bits (block_coverage.hpp).
std::uint64_t coverageMask(const TriangleCoverage& tri, int bx, int by, const PixelRect& clip) {
  const int c0 = std::max(clip.x0 - bx, 0), c1 = std::min(clip.x1 - bx, kBlockSize);
  const int r0 = std::max(clip.y0 - by, 0), r1 = std::min(clip.y1 - by, kBlockSize);
  const std::int64_t x = pixelCentreFixed(bx);
  const std::int64_t y = pixelCentreFixed(by);
  BlockEdges edges{};
  for (int k = 0; k < 3; ++k) {
    edges.origin[k] = tri.edges[k].at(x, y);
    edges.stepX[k] = tri.edges[k].a * kSubpixelOne;
    edges.stepY[k] = tri.edges[k].b * kSubpixelOne;
  }
  // Up to this many pixels the scalar loop; recode_raster_bench and whole runs timed 0, 4, 8
  // and 64 here without a measurable difference.
  constexpr int kScalarArea = 4;
  if ((c1 - c0) * (r1 - r0) <= kScalarArea)
    return blockCoverageScalar(edges, c0, c1, r0, r1);
  return blockCoverageSimd(edges, c0, c1, r0, r1);
}

int alignDown(int v, int a) {
  return v >= 0 ? v / a * a : -((-v + a - 1) / a) * a;
}

// Clipped areas up to this many pixels that span more than one block (a small triangle over a
// block's edge: for one of a few pixels, about two in five) take smallAreaBlocks.
constexpr int kSmallArea = 16;

// The coverage of a small clipped area that spans two or more blocks, each block's pixels in
// the area tested on their own (coverageMask), handed out in the traversal's order: tiles row
// by row, then each tile's blocks row by row. The tile and block tests of the general loop
// could only reject or accept what the per-pixel test decides, and for a few pixels they cost
// more than it.
void smallAreaBlocks(const TriangleCoverage& tri, const PixelRect& area, int firstX, int firstY,
                     BlockSink& sink, TraversalStats& st) {
  // kSmallArea pixels span at most three blocks along either axis, and three blocks (24
  // pixels) at most two tiles.
  constexpr int kMaxSpan = 3;
  const int columns = (area.x1 - 1 - firstX) / kBlockSize + 1;
  const int rows = (area.y1 - 1 - firstY) / kBlockSize + 1;
  RECODE_INVARIANT(columns <= kMaxSpan && rows <= kMaxSpan, "a small area spans three blocks");
  // The first block index of the second tile along each axis (the count when all lie in one).
  const auto tileSplit = [](int first, int count) {
    int n = 1;
    while (n < count && (first + n * kBlockSize) / kTileSize == first / kTileSize)
      ++n;
    return n;
  };
  const int splitX = tileSplit(firstX, columns), splitY = tileSplit(firstY, rows);
  const int tileRows[3] = {0, splitY, rows}, tileColumns[3] = {0, splitX, columns};
  for (int ty = 0; ty < 2; ++ty) {
    for (int tx = 0; tx < 2; ++tx) {
      for (int j = tileRows[ty]; j < tileRows[ty + 1]; ++j) {
        for (int i = tileColumns[tx]; i < tileColumns[tx + 1]; ++i) {
          ++st.blocksPartial;
          const int bx = firstX + i * kBlockSize, by = firstY + j * kBlockSize;
          const std::uint64_t mask = coverageMask(tri, bx, by, area);
          if (mask != 0)
            sink.coveredBlock(bx, by, mask);
        }
      }
    }
  }
}

}  // namespace

std::uint64_t blockMaskInside(int x, int y, const PixelRect& rect) {
  if (x >= rect.x0 && y >= rect.y0 && x + kBlockSize <= rect.x1 && y + kBlockSize <= rect.y1)
    return ~std::uint64_t{0};  // the common case: the whole block
  const int c0 = std::max(rect.x0 - x, 0), c1 = std::min(rect.x1 - x, kBlockSize);
  const int r0 = std::max(rect.y0 - y, 0), r1 = std::min(rect.y1 - y, kBlockSize);
  if (c0 >= c1 || r0 >= r1)
    return 0;
  const std::uint64_t rowBits = ((std::uint64_t{1} << (c1 - c0)) - 1) << c0;
  // Bit 0 of each row in [r0, r1); times rowBits (below 256) copies rowBits into those rows.
  const int rows = r1 - r0;
  const std::uint64_t span =
      rows == kBlockSize ? ~std::uint64_t{0} : ((std::uint64_t{1} << (8 * rows)) - 1) << (8 * r0);
  return rowBits * (span & 0x0101010101010101ULL);
}

namespace {

// One row of 8x8 blocks at y = by inside a tile that testRegion did not reject: the blocks
// from bx0 (aligned) up to bx1, each tested (unless the tile was accepted whole) and handed to
// the sink with its coverage.
void traverseTileRow(const TriangleCoverage& tri, RegionTest tileTest, const PixelRect& area,
                     int bx0, int bx1, int by, BlockSink& sink, TraversalStats& st) {
  // Blocks j = 0 .. count - 1 of this row in this tile are at bx0 + 8 j; each meets the area
  // (bx0 and by are aligned down from it). Those outside [keep.lo, keep.hi] are the ones
  // testRegion rejects.
  const std::int64_t count = (bx1 - bx0 + kBlockSize - 1) / kBlockSize;
  std::int64_t jFirst = 0, jEnd = count;
  // The span costs three divisions: for a row of a few blocks (a small triangle's) testing each
  // block is cheaper.
  constexpr std::int64_t kFewBlocks = 3;
  if (tileTest == RegionTest::Partial && count > kFewBlocks) {
    const BlockSpan keep = unrejectedBlocks(tri, by);
    if (keep.lo > bx0)
      jFirst = std::min(count, (keep.lo - bx0 + kBlockSize - 1) / kBlockSize);
    jEnd = keep.hi < bx0 ? 0 : std::min(count, (keep.hi - bx0) / kBlockSize + 1);
    jEnd = std::max(jEnd, jFirst);
    st.blocksRejected += static_cast<std::uint64_t>(jFirst + (count - jEnd));
  }
  for (std::int64_t j = jFirst; j < jEnd; ++j) {
    const int bx = bx0 + static_cast<int>(j) * kBlockSize;
    const std::uint64_t inClip = blockMaskInside(bx, by, area);
    if (inClip == 0)
      continue;
    std::uint64_t mask;
    if (tileTest == RegionTest::Accept) {
      mask = inClip;
    } else {
      const RegionTest blockTest = testRegion(tri, bx, by, kBlockSize);
      if (blockTest == RegionTest::Reject) {
        ++st.blocksRejected;
        continue;
      }
      if (blockTest == RegionTest::Accept) {
        ++st.blocksAccepted;
        mask = inClip;
      } else {
        ++st.blocksPartial;
        mask = coverageMask(tri, bx, by, area);
      }
    }
    if (mask == 0)
      continue;
    RECODE_INVARIANT(bx % kBlockSize == 0 && by % kBlockSize == 0,
                     "blocks are aligned to the 8x8 grid");
    RECODE_INVARIANT((mask & ~inClip) == 0, "a block's coverage lies inside the clip");
    sink.coveredBlock(bx, by, mask);
  }
}

}  // namespace

void traverseTriangle(const TriangleCoverage& tri, const PixelRect& clip, BlockSink& sink,
                      TraversalStats* stats) {
  RECODE_INVARIANT(clip.x0 >= 0 && clip.y0 >= 0 && clip.x1 <= kMaxFramebufferSize &&
                       clip.y1 <= kMaxFramebufferSize,
                   "the clip rectangle lies inside the largest framebuffer");
  const PixelRect area = tri.bounds.intersect(clip);
  if (area.empty())
    return;
  TraversalStats local;
  TraversalStats& st = stats ? *stats : local;

  // Pixels inside one 8x8 block, as for most small triangles: their coverage straight away.
  // The tile and block tests could only reject or accept what the per-pixel test decides.
  const int firstX = alignDown(area.x0, kBlockSize), firstY = alignDown(area.y0, kBlockSize);
  if (area.x1 <= firstX + kBlockSize && area.y1 <= firstY + kBlockSize) {
    ++st.blocksPartial;
    const std::uint64_t mask = coverageMask(tri, firstX, firstY, area);
    if (mask != 0)
      sink.coveredBlock(firstX, firstY, mask);
    return;
  }
  if (area.width() * area.height() <= kSmallArea) {
    smallAreaBlocks(tri, area, firstX, firstY, sink, st);
    return;
  }

  for (int ty = alignDown(area.y0, kTileSize); ty < area.y1; ty += kTileSize) {
    for (int tx = alignDown(area.x0, kTileSize); tx < area.x1; tx += kTileSize) {
      const RegionTest tileTest = testRegion(tri, tx, ty, kTileSize);
      if (tileTest == RegionTest::Reject) {
        ++st.tilesRejected;
        continue;
      }
      if (tileTest == RegionTest::Accept)
        ++st.tilesAccepted;
      const int by0 = std::max(ty, alignDown(area.y0, kBlockSize));
      const int bx0 = std::max(tx, alignDown(area.x0, kBlockSize));
      const int by1 = std::min(ty + kTileSize, area.y1);
      const int bx1 = std::min(tx + kTileSize, area.x1);
      for (int by = by0; by < by1; by += kBlockSize)
        traverseTileRow(tri, tileTest, area, bx0, bx1, by, sink, st);
    }
  }
}

}  // namespace recode::raster
