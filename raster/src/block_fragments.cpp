// The fragment stage over an 8x8 block, one pixel at a time and in SIMD (block_fragments.hpp).
// The SIMD version is compiled once per Highway target (foreach_target.h re-includes this
// file) and dispatched at run time. It evaluates the same double operations in the same order
// (a multiply and two adds, no contraction: the raster layer builds with -ffp-contract=off)
// and the same integer tests on int32 lanes, which hold every stored value exactly (depths
// below 2^24, stencils below 2^8), so it gives the same bytes.
#include "recode/raster/block_fragments.hpp"

#include <cstdint>

#if RECODE_RASTER_HWY
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "block_fragments.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace recode::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// compare() (fragment_stage.hpp) on int32 lanes.
template <class D, class V>
HWY_INLINE hn::Mask<D> CompareLanes(D d, CompareFunc func, V incoming, V stored) {
  switch (func) {
    case CompareFunc::Never:
      return hn::FirstN(d, 0);
    case CompareFunc::Less:
      return hn::Lt(incoming, stored);
    case CompareFunc::Equal:
      return hn::Eq(incoming, stored);
    case CompareFunc::LEqual:
      return hn::Not(hn::Gt(incoming, stored));
    case CompareFunc::Greater:
      return hn::Gt(incoming, stored);
    case CompareFunc::NotEqual:
      return hn::Ne(incoming, stored);
    case CompareFunc::GEqual:
      return hn::Not(hn::Lt(incoming, stored));
    case CompareFunc::Always:
      break;
  }
  return hn::FirstN(d, hn::Lanes(d));
}

// applyStencilOp() on int32 lanes holding 0..255.
template <class D, class V>
HWY_INLINE V StencilOpLanes(D d, StencilOp op, V value, std::uint8_t ref) {
  const V one = hn::Set(d, 1), full = hn::Set(d, 0xFF);
  switch (op) {
    case StencilOp::Keep:
      return value;
    case StencilOp::Zero:
      return hn::Zero(d);
    case StencilOp::Replace:
      return hn::Set(d, ref);
    case StencilOp::Incr:
      return hn::Min(hn::Add(value, one), full);
    case StencilOp::IncrWrap:
      return hn::And(hn::Add(value, one), full);
    case StencilOp::Decr:
      return hn::Max(hn::Sub(value, one), hn::Zero(d));
    case StencilOp::DecrWrap:
      return hn::And(hn::Sub(value, one), full);
    case StencilOp::Invert:
      return hn::Xor(value, full);
  }
  return value;
}

// The state a fragment reads, copied out of the RenderState once per block: the buffer stores
// go through a uint8_t pointer, which may alias anything, so fields read through the state
// would be loaded again after every store.
struct FragmentState {
  CompareFunc stencilFunc;
  CompareFunc depthFunc;
  std::uint8_t stencilRef;
  std::uint8_t stencilValueMask;
  std::uint8_t stencilWriteMask;
  bool depthWrite;
  StencilOps ops;
};

// Row r of the block, all 8 pixels covered, `lanes` pixels per step: zx holds the row-invariant
// part of each column's depth, ty the row's.
template <class DD>
HWY_INLINE void ApplyFullRow(DD dd, const FragmentState& s, const BlockFragments& b,
                             const double* zx, double ty, int r) {
  const hn::Rebind<std::int32_t, DD> di;
  const hn::Rebind<std::uint8_t, DD> d8;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const StencilOps& ops = s.ops;
  auto* depthRow = reinterpret_cast<std::int32_t*>(b.depth + r * b.stride);
  std::uint8_t* stencilRow = b.stencil + r * b.stride;
  const auto valueMask = hn::Set(di, s.stencilValueMask);
  const auto writeMask = hn::Set(di, s.stencilWriteMask);
  const auto stencilRef = hn::Set(di, s.stencilRef & s.stencilValueMask);
  for (int j = 0; j < 8; j += lanes) {
    // quantizeDepth: 0 unless z > 0 (NaN too), kDepthMax from 1 on, else the scaled value
    // rounded by adding and subtracting kRoundToIntegerBias.
    const auto z = hn::Add(hn::Load(dd, zx + j), hn::Set(dd, ty));
    const auto bias = hn::Set(dd, kRoundToIntegerBias);
    const auto scaled = hn::Mul(z, hn::Set(dd, static_cast<double>(kDepthMax)));
    auto q = hn::Sub(hn::Add(scaled, bias), bias);
    q = hn::IfThenElse(z >= hn::Set(dd, 1.0), hn::Set(dd, static_cast<double>(kDepthMax)), q);
    q = hn::IfThenElseZero(hn::Gt(z, hn::Zero(dd)), q);
    const auto incoming = hn::DemoteTo(di, q);  // an integer in [0, 2^24): exact

    const auto stored = hn::LoadU(di, depthRow + j);
    const auto old = hn::PromoteTo(di, hn::LoadU(d8, stencilRow + j));
    const auto stencilPass = CompareLanes(di, s.stencilFunc, stencilRef, hn::And(old, valueMask));
    const auto depthPass = CompareLanes(di, s.depthFunc, incoming, stored);
    if (s.stencilWriteMask != 0) {  // else no stencil bit can change
      const auto stencilFail = hn::Not(stencilPass);
      const auto depthFail = hn::AndNot(depthPass, stencilPass);
      const auto updated = hn::IfThenElse(
          stencilFail, StencilOpLanes(di, ops.stencilFail, old, s.stencilRef),
          hn::IfThenElse(depthFail, StencilOpLanes(di, ops.depthFail, old, s.stencilRef),
                         StencilOpLanes(di, ops.depthPass, old, s.stencilRef)));
      const auto written = hn::Or(hn::And(updated, writeMask), hn::AndNot(writeMask, old));
      hn::StoreU(hn::DemoteTo(d8, written), d8, stencilRow + j);
    }
    if (s.depthWrite)
      hn::StoreU(hn::IfThenElse(hn::And(stencilPass, depthPass), incoming, stored), di,
                 depthRow + j);
  }
}

int ApplyBlock(const BlockFragments& b, std::uint64_t mask) {
  const hn::CappedTag<double, 8> dd;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const DepthPlane& p = *b.plane;
  const RenderState& state = *b.state;
  const FragmentState s{state.stencilFunc,
                        state.depthFunc,
                        state.stencilRef,
                        state.stencilValueMask,
                        state.stencilWriteMask,
                        state.depthWrite,
                        *b.ops};
  // zx[c] = z0 + dzdx (X_c - x0) for the block's columns, as DepthPlane::at makes it. X_c - x0
  // is base + 256 c: integers far below 2^53, so the double sum is exact and equals the
  // converted integer difference the one-pixel path multiplies.
  alignas(64) double zx[8];
  const auto base = hn::Set(dd, static_cast<double>(pixelCentreFixed(b.x) - p.x0));
  const auto step = hn::Set(dd, static_cast<double>(kSubpixelOne));
  for (int j = 0; j < 8; j += lanes) {
    const auto offset = hn::Add(base, hn::Mul(hn::Iota(dd, static_cast<double>(j)), step));
    hn::Store(hn::Add(hn::Set(dd, p.z0), hn::Mul(hn::Set(dd, p.dzdx), offset)), dd, zx + j);
  }
  int applied = 0;
  while (mask != 0) {
    const int r = __builtin_ctzll(mask) / 8;
    const auto bits = static_cast<unsigned>((mask >> (8 * r)) & 0xFF);
    mask &= ~(std::uint64_t{0xFF} << (8 * r));
    if (bits == 0xFF) {
      const double ty = p.dzdy * static_cast<double>(pixelCentreFixed(b.y + r) - p.y0);
      ApplyFullRow(dd, s, b, zx, ty, r);
      applied += 8;
    } else {
      applied += applyRowFragments(b, r, bits);
    }
  }
  return applied;
}

}  // namespace HWY_NAMESPACE
}  // namespace recode::raster
HWY_AFTER_NAMESPACE();
#endif  // RECODE_RASTER_HWY

#if !RECODE_RASTER_HWY || HWY_ONCE
namespace recode::raster {

#if RECODE_RASTER_HWY
HWY_EXPORT(ApplyBlock);

int detail::applyBlockFragmentsSimd(const BlockFragments& block, std::uint64_t mask) {
  return HWY_DYNAMIC_DISPATCH(ApplyBlock)(block, mask);
}
#else
int detail::applyBlockFragmentsSimd(const BlockFragments& block, std::uint64_t mask) {
  return applyBlockFragmentsScalar(block, mask);
}
#endif  // RECODE_RASTER_HWY

}  // namespace recode::raster
#endif  // !RECODE_RASTER_HWY || HWY_ONCE
