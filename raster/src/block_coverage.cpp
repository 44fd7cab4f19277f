// The 8x8 block coverage test, scalar and SIMD (block_coverage.hpp). The SIMD version is
// compiled once per Highway target (foreach_target.h re-includes this file) and dispatched at
// run time; both evaluate the same exact integer edge values, so they give the same bits. A
// build without Highway (RECODE_RASTER_HWY unset) has the scalar version only.
#include "recode/raster/block_coverage.hpp"

#include <cstdint>
#include <vector>

#if RECODE_RASTER_HWY
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "block_coverage.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/targets.h>

HWY_BEFORE_NAMESPACE();
namespace recode::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per row of the block, the edge values of its 8 pixels are the row's value at column 0 plus
// c * stepX (precomputed per lane), tested as the scalar loop tests them: the OR of the three
// has its sign bit clear exactly when all three are non-negative.
std::uint64_t BlockCoverageRows(const BlockEdges& edges, int c0, int c1, int r0, int r1) {
  const hn::CappedTag<std::int64_t, 8> d;
  const auto lanes = static_cast<int>(hn::Lanes(d));
  // offsets[k][c] = c * stepX[k], written a vector at a time from the bits of c (selects and
  // adds: not every target has a 64-bit multiply). Vector stores, as the loop's loads are:
  // scalar stores read back as a vector could not be forwarded.
  alignas(64) std::int64_t offsets[3][8];
  const auto zero = hn::Zero(d);
  for (int j = 0; j < 8; j += lanes) {
    const auto column = hn::Iota(d, j);
    const auto has1 = hn::Ne(hn::And(column, hn::Set(d, 1)), zero);
    const auto has2 = hn::Ne(hn::And(column, hn::Set(d, 2)), zero);
    const auto has4 = hn::Ne(hn::And(column, hn::Set(d, 4)), zero);
    for (int k = 0; k < 3; ++k) {
      const std::int64_t step = edges.stepX[k];
      const auto offset = hn::Add(hn::Add(hn::IfThenElseZero(has1, hn::Set(d, step)),
                                          hn::IfThenElseZero(has2, hn::Set(d, 2 * step))),
                                  hn::IfThenElseZero(has4, hn::Set(d, 4 * step)));
      hn::Store(offset, d, offsets[k] + j);
    }
  }
  std::int64_t row[3];
  for (int k = 0; k < 3; ++k)
    row[k] = edges.origin[k] + r0 * edges.stepY[k];
  const std::uint64_t columns = ((std::uint64_t{1} << (c1 - c0)) - 1) << c0;
  const auto minusOne = hn::Set(d, -1);
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r) {
    std::uint64_t rowBits = 0;
    for (int j = (c0 / lanes) * lanes; j < c1; j += lanes) {
      const auto e0 = hn::Add(hn::Set(d, row[0]), hn::Load(d, offsets[0] + j));
      const auto e1 = hn::Add(hn::Set(d, row[1]), hn::Load(d, offsets[1] + j));
      const auto e2 = hn::Add(hn::Set(d, row[2]), hn::Load(d, offsets[2] + j));
      const auto inside = hn::Gt(hn::Or(e0, hn::Or(e1, e2)), minusOne);
      std::uint8_t bits[8] = {};
      hn::StoreMaskBits(d, inside, bits);
      rowBits |= static_cast<std::uint64_t>(bits[0]) << j;
    }
    mask |= (rowBits & columns) << (r * 8);
    for (int k = 0; k < 3; ++k)
      row[k] += edges.stepY[k];
  }
  return mask;
}

}  // namespace HWY_NAMESPACE
}  // namespace recode::raster
HWY_AFTER_NAMESPACE();
#endif  // RECODE_RASTER_HWY

#if !RECODE_RASTER_HWY || HWY_ONCE
namespace recode::raster {

std::uint64_t blockCoverageScalar(const BlockEdges& edges, int c0, int c1, int r0, int r1) {
  std::int64_t rowStart[3];
  for (int k = 0; k < 3; ++k)
    rowStart[k] = edges.origin[k] + c0 * edges.stepX[k] + r0 * edges.stepY[k];
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r) {
    std::int64_t e0 = rowStart[0], e1 = rowStart[1], e2 = rowStart[2];
    for (int c = c0; c < c1; ++c) {
      const bool inside = (e0 | e1 | e2) >= 0;  // all three non-negative
      mask |= static_cast<std::uint64_t>(inside) << (r * 8 + c);
      e0 += edges.stepX[0];
      e1 += edges.stepX[1];
      e2 += edges.stepX[2];
    }
    for (int k = 0; k < 3; ++k)
      rowStart[k] += edges.stepY[k];
  }
  return mask;
}

#if RECODE_RASTER_HWY
HWY_EXPORT(BlockCoverageRows);

std::uint64_t blockCoverageSimd(const BlockEdges& edges, int c0, int c1, int r0, int r1) {
  return HWY_DYNAMIC_DISPATCH(BlockCoverageRows)(edges, c0, c1, r0, r1);
}

void forEachSimdTarget(const std::function<void(const char* targetName)>& visit) {
  // Listed before the loop: the list follows the target chosen for the test.
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  for (const std::int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
    visit(hwy::TargetName(target));
  }
  hwy::SetSupportedTargetsForTest(0);
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
}
#else
std::uint64_t blockCoverageSimd(const BlockEdges& edges, int c0, int c1, int r0, int r1) {
  return blockCoverageScalar(edges, c0, c1, r0, r1);
}

void forEachSimdTarget(const std::function<void(const char* targetName)>& visit) {
  visit("none (built without Highway: the scalar loop)");
}
#endif  // RECODE_RASTER_HWY

}  // namespace recode::raster
#endif  // !RECODE_RASTER_HWY || HWY_ONCE
