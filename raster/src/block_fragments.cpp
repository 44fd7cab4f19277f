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

// Rows with fewer covered pixels than this go pixel by pixel: a vector step costs about as
// much as two pixels one at a time.
constexpr int kMinVectorRowPixels = 3;

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

// The compare functions and stencil ops a kernel applies, read from the state: the general
// kernel, for any state.
struct StateFuncs {
  static constexpr int kKernel = -1;
  static CompareFunc stencilFunc(const FragmentState& s) { return s.stencilFunc; }
  static CompareFunc depthFunc(const FragmentState& s) { return s.depthFunc; }
  static const StencilOps& ops(const FragmentState& s) { return s.ops; }
};

// Those of detail::kCompiledFragmentFuncs[K], known when the kernel is compiled: the switches
// of CompareLanes and StencilOpLanes fold to the one case.
template <int K>
struct CompiledFuncs {
  static constexpr int kKernel = K;
  static constexpr detail::FragmentFuncs kFuncs = detail::kCompiledFragmentFuncs[K];
  static constexpr CompareFunc stencilFunc(const FragmentState&) { return kFuncs.stencilFunc; }
  static constexpr CompareFunc depthFunc(const FragmentState&) { return kFuncs.depthFunc; }
  static constexpr const StencilOps& ops(const FragmentState&) { return kFuncs.ops; }
};

// quantizeDepth on lanes: 0 unless z > 0 (NaN too), kDepthMax from 1 on, else the scaled value
// rounded by adding and subtracting kRoundToIntegerBias. The result is an integer in [0, 2^24),
// so the conversion is exact.
template <class DD, class DI>
HWY_INLINE hn::Vec<DI> QuantizeLanes(DD dd, DI di, hn::Vec<DD> z) {
  const auto bias = hn::Set(dd, kRoundToIntegerBias);
  const auto depthMax = hn::Set(dd, static_cast<double>(kDepthMax));
  auto q = hn::Sub(hn::Add(hn::Mul(z, depthMax), bias), bias);
  // From z >= 1 on the product is at least kDepthMax, below 1 at most kDepthMax (rounding is
  // monotonic), so the clamp is a Min; a NaN's lane is zeroed next whatever Min gave it.
  q = hn::Min(q, depthMax);
  q = hn::IfThenElseZero(hn::Gt(z, hn::Zero(dd)), q);
  return hn::DemoteTo(di, q);
}

// What the tests and ops leave in a vector of covered pixels.
template <class DI>
struct LanesAfter {
  hn::Vec<DI> stencil;
  hn::Vec<DI> depth;
};

// applyFragment() on int32 lanes: the incoming and stored depths and the old stencils.
template <class Funcs, class DI>
HWY_INLINE LanesAfter<DI> FragmentLanes(DI di, const FragmentState& s, hn::Vec<DI> incoming,
                                        hn::Vec<DI> stored, hn::Vec<DI> old) {
  const StencilOps& ops = Funcs::ops(s);
  const auto valueMask = hn::Set(di, s.stencilValueMask);
  const auto writeMask = hn::Set(di, s.stencilWriteMask);
  const auto stencilRef = hn::Set(di, s.stencilRef & s.stencilValueMask);
  const auto stencilPass =
      CompareLanes(di, Funcs::stencilFunc(s), stencilRef, hn::And(old, valueMask));
  const auto depthPass = CompareLanes(di, Funcs::depthFunc(s), incoming, stored);
  LanesAfter<DI> after{old, stored};
  if (s.stencilWriteMask != 0) {  // else no stencil bit can change
    const auto stencilFail = hn::Not(stencilPass);
    const auto depthFail = hn::AndNot(depthPass, stencilPass);
    const auto updated = hn::IfThenElse(
        stencilFail, StencilOpLanes(di, ops.stencilFail, old, s.stencilRef),
        hn::IfThenElse(depthFail, StencilOpLanes(di, ops.depthFail, old, s.stencilRef),
                       StencilOpLanes(di, ops.depthPass, old, s.stencilRef)));
    after.stencil = hn::Or(hn::And(updated, writeMask), hn::AndNot(writeMask, old));
  }
  if (s.depthWrite)
    after.depth = hn::IfThenElse(hn::And(stencilPass, depthPass), incoming, stored);
  return after;
}

// The lanes whose pixel is covered: bit `column` of the lane's row `bits` (bit c: column c).
template <class DI>
HWY_INLINE hn::Mask<DI> CoveredLanes(DI di, hn::Vec<DI> bits, hn::Vec<DI> column) {
  return hn::Ne(hn::And(hn::Shr(bits, column), hn::Set(di, 1)), hn::Zero(di));
}

// A partial row's lanes keep what they held where no pixel is covered.
template <class DI>
HWY_INLINE void KeepUncovered(hn::Mask<DI> covered, hn::Vec<DI> old, hn::Vec<DI> stored,
                              LanesAfter<DI>& after) {
  after.stencil = hn::IfThenElse(covered, after.stencil, old);
  after.depth = hn::IfThenElse(covered, after.depth, stored);
}

// Row r of the block, the pixels of `bits` covered (all 8 when kFull), `lanes` pixels per step:
// zx holds the row-invariant part of each column's depth, ty the row's. A lane of an uncovered
// pixel is computed and then written back unchanged.
template <bool kFull, class Funcs, class DD>
HWY_INLINE void ApplyRow(DD dd, const FragmentState& s, const BlockFragments& b, const double* zx,
                         double ty, int r, unsigned bits) {
  const hn::Rebind<std::int32_t, DD> di;
  const hn::Rebind<std::uint32_t, DD> du;
  const hn::Rebind<std::uint8_t, DD> d8;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  auto* depthRow = reinterpret_cast<std::int32_t*>(b.depth + r * b.stride);
  std::uint8_t* stencilRow = b.stencil + r * b.stride;
  for (int j = 0; j < 8; j += lanes) {
    const auto incoming = QuantizeLanes(dd, di, hn::Add(hn::Load(dd, zx + j), hn::Set(dd, ty)));
    const auto stored = hn::LoadU(di, depthRow + j);
    const auto old = hn::PromoteTo(di, hn::LoadU(d8, stencilRow + j));
    auto after = FragmentLanes<Funcs>(di, s, incoming, stored, old);
    if constexpr (!kFull)
      KeepUncovered(CoveredLanes(di, hn::Set(di, static_cast<std::int32_t>(bits)), hn::Iota(di, j)),
                    old, stored, after);
    if (s.stencilWriteMask != 0)
      hn::StoreU(hn::TruncateTo(d8, hn::BitCast(du, after.stencil)), d8, stencilRow + j);
    if (s.depthWrite)
      hn::StoreU(after.depth, di, depthRow + j);
  }
}

#if HWY_TARGET != HWY_SCALAR  // one-lane vectors have no halves
// Rows r and r + 1 (bits0 and bits1 covered; all 16 pixels when kFull) in vectors twice as
// wide for the integer work: the depths are doubles, so a double vector holds half as many
// pixels as an int32 one of the same width.
template <bool kFull, class Funcs, class DD>
HWY_INLINE void ApplyRowPair(DD dd, const FragmentState& s, const BlockFragments& b,
                             const double* zx, double ty0, double ty1, int r, unsigned bits0,
                             unsigned bits1) {
  const hn::Rebind<std::int32_t, DD> di;
  const hn::Twice<decltype(di)> d2i;
  const hn::Rebind<std::uint32_t, decltype(d2i)> d2u;
  const hn::Rebind<std::uint8_t, DD> d8;
  const hn::Rebind<std::uint8_t, decltype(d2i)> d28;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  auto* depth0 = reinterpret_cast<std::int32_t*>(b.depth + r * b.stride);
  auto* depth1 = depth0 + b.stride;
  std::uint8_t* stencil0 = b.stencil + r * b.stride;
  std::uint8_t* stencil1 = stencil0 + b.stride;
  for (int j = 0; j < 8; j += lanes) {
    const auto zc = hn::Load(dd, zx + j);
    const auto incoming = hn::Combine(d2i, QuantizeLanes(dd, di, hn::Add(zc, hn::Set(dd, ty1))),
                                      QuantizeLanes(dd, di, hn::Add(zc, hn::Set(dd, ty0))));
    const auto stored = hn::Combine(d2i, hn::LoadU(di, depth1 + j), hn::LoadU(di, depth0 + j));
    const auto old = hn::PromoteTo(
        d2i, hn::Combine(d28, hn::LoadU(d8, stencil1 + j), hn::LoadU(d8, stencil0 + j)));
    auto after = FragmentLanes<Funcs>(d2i, s, incoming, stored, old);
    if constexpr (!kFull) {
      // Lane k of the low half is column j + k of row r, of the high half of row r + 1.
      const auto bits = hn::Combine(d2i, hn::Set(di, static_cast<std::int32_t>(bits1)),
                                    hn::Set(di, static_cast<std::int32_t>(bits0)));
      const auto column = hn::Combine(d2i, hn::Iota(di, j), hn::Iota(di, j));
      KeepUncovered(CoveredLanes(d2i, bits, column), old, stored, after);
    }
    if (s.stencilWriteMask != 0) {
      const auto bytes = hn::TruncateTo(d28, hn::BitCast(d2u, after.stencil));
      hn::StoreU(hn::LowerHalf(d8, bytes), d8, stencil0 + j);
      hn::StoreU(hn::UpperHalf(d8, bytes), d8, stencil1 + j);
    }
    if (s.depthWrite) {
      hn::StoreU(hn::LowerHalf(di, after.depth), di, depth0 + j);
      hn::StoreU(hn::UpperHalf(di, after.depth), di, depth1 + j);
    }
  }
}
#endif

template <class Funcs>
HWY_NOINLINE int ApplyBlockWith(const BlockFragments& b, const FragmentState& s,
                                std::uint64_t mask) {
  const hn::CappedTag<double, 8> dd;
  const int lanes = static_cast<int>(hn::Lanes(dd));
  const DepthPlane& p = *b.plane;
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
  const auto rowY = [&](int row) {
    return p.dzdy * static_cast<double>(pixelCentreFixed(b.y + row) - p.y0);
  };
  const auto rowBits = [&](int row) { return static_cast<unsigned>((mask >> (8 * row)) & 0xFF); };
  const std::uint64_t perRow = detail::pixelsPerRow(mask);
  const auto rowPixels = [&](int row) { return static_cast<int>((perRow >> (8 * row)) & 0xFF); };
  // A full row, or a partial one with enough pixels in a block whose columns all lie inside the
  // buffers (a full row's do: its pixels are covered).
  const auto vectorRow = [&](int row) {
    return rowBits(row) == 0xFF || (b.wholeColumns && rowPixels(row) >= kMinVectorRowPixels);
  };
  for (int r = 0; r < 8; ++r) {
    const unsigned bits = rowBits(r);
    if (!vectorRow(r)) {
      if (bits != 0)
        applyRowFragmentsWith<Funcs::kKernel>(b, r, bits);
      continue;
    }
#if HWY_TARGET != HWY_SCALAR
    if (r < 7 && vectorRow(r + 1)) {
      const unsigned next = rowBits(r + 1);
      if ((bits & next) == 0xFF)
        ApplyRowPair<true, Funcs>(dd, s, b, zx, rowY(r), rowY(r + 1), r, bits, next);
      else
        ApplyRowPair<false, Funcs>(dd, s, b, zx, rowY(r), rowY(r + 1), r, bits, next);
      ++r;
      continue;
    }
#endif
    if (bits == 0xFF)
      ApplyRow<true, Funcs>(dd, s, b, zx, rowY(r), r, bits);
    else
      ApplyRow<false, Funcs>(dd, s, b, zx, rowY(r), r, bits);
  }
  return detail::pixelsInBlock(perRow);
}

int ApplyBlock(const BlockFragments& b, std::uint64_t mask) {
  const RenderState& state = *b.state;
  const FragmentState s{state.stencilFunc,
                        state.depthFunc,
                        state.stencilRef,
                        state.stencilValueMask,
                        state.stencilWriteMask,
                        state.depthWrite,
                        *b.ops};
  static_assert(detail::kCompiledFragmentKernels == 5, "one case per compiled kernel");
  switch (b.kernel) {  // the caller's detail::compiledFragmentKernel, found once per draw
    case 0:
      return ApplyBlockWith<CompiledFuncs<0>>(b, s, mask);
    case 1:
      return ApplyBlockWith<CompiledFuncs<1>>(b, s, mask);
    case 2:
      return ApplyBlockWith<CompiledFuncs<2>>(b, s, mask);
    case 3:
      return ApplyBlockWith<CompiledFuncs<3>>(b, s, mask);
    case 4:
      return ApplyBlockWith<CompiledFuncs<4>>(b, s, mask);
    default:
      return ApplyBlockWith<StateFuncs>(b, s, mask);
  }
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
