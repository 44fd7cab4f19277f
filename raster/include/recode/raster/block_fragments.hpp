#pragma once
// The fragment stage over one 8x8 block of covered pixels (docs/rasterization.md, section 6):
// each pixel's depth from the triangle's plane, quantized, then the stencil and depth tests and
// writes of fragment_stage.hpp. A block's pixels are distinct, so their fragments are
// independent and may be applied in any order or all at once. Two implementations give the
// same bytes: one pixel at a time, and a SIMD one (Google Highway, chosen at run time; optional)
// that makes the columns' part of the depth once per block and applies each fully covered row
// of 8 pixels in one to four vector steps, the other rows one pixel at a time. Tests compare
// them on every target (forEachSimdTarget, block_coverage.hpp).

#include <cstddef>
#include <cstdint>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/fragment_stage.hpp"
#include "recode/raster/invariants.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster {

struct BlockFragments;

namespace detail {
// The SIMD version (block_fragments.cpp): rows with a few covered pixels or more in vectors,
// two rows at a time where both are, the sparser rows one pixel at a time.
int applyBlockFragmentsSimd(const BlockFragments& block, std::uint64_t mask);

// Byte r of the result is the number of bits set in byte r (row r) of the mask. Bit arithmetic,
// since the baseline x86-64 has no popcount instruction and the builtin would be a call.
inline std::uint64_t pixelsPerRow(std::uint64_t mask) {
  mask = mask - ((mask >> 1) & 0x5555555555555555ULL);
  mask = (mask & 0x3333333333333333ULL) + ((mask >> 2) & 0x3333333333333333ULL);
  return (mask + (mask >> 4)) & 0x0F0F0F0F0F0F0F0FULL;
}

// The sum of the bytes of pixelsPerRow: the covered pixels of the block.
inline int pixelsInBlock(std::uint64_t perRow) {
  return static_cast<int>((perRow * 0x0101010101010101ULL) >> 56);
}

// The compare functions and stencil ops of one fragment kernel.
struct FragmentFuncs {
  CompareFunc stencilFunc;
  CompareFunc depthFunc;
  StencilOps ops;
};

// The SIMD version has a kernel compiled for each of these, the states of RECODE's passes
// (core/pair/src/pair_passes.hpp: RenderSetZ, RenderTestZ, loading Amin, the Amin test, the
// two ends of the overlap interval), so that the compare and stencil-op tables fold away
// instead of being looked up per vector step. Any other state takes the general kernel, which
// reads them from the state; every kernel gives the one-pixel version's bytes. The references
// and masks stay run-time values in all of them.
inline constexpr FragmentFuncs kCompiledFragmentFuncs[] = {
    {CompareFunc::Always,
     CompareFunc::GEqual,
     {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace}},
    {CompareFunc::LEqual, CompareFunc::LEqual, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr}},
    {CompareFunc::Always, CompareFunc::LEqual, {StencilOp::Keep, StencilOp::Keep, StencilOp::Keep}},
    {CompareFunc::LEqual,
     CompareFunc::GEqual,
     {StencilOp::Invert, StencilOp::Keep, StencilOp::Invert}},
    {CompareFunc::Always, CompareFunc::GEqual, {StencilOp::Keep, StencilOp::Keep, StencilOp::Keep}},
};
inline constexpr int kCompiledFragmentKernels =
    static_cast<int>(sizeof(kCompiledFragmentFuncs) / sizeof(kCompiledFragmentFuncs[0]));

// The index in kCompiledFragmentFuncs of the kernel for this state and these ops, -1 for the
// general kernel.
inline int compiledFragmentKernel(const RenderState& state, const StencilOps& ops) {
  for (int k = 0; k < kCompiledFragmentKernels; ++k) {
    const FragmentFuncs& f = kCompiledFragmentFuncs[k];
    if (f.stencilFunc == state.stencilFunc && f.depthFunc == state.depthFunc && f.ops == ops)
      return k;
  }
  return -1;
}

// Blocks with fewer covered pixels than this (a small triangle's, or a thin sliver of a large
// one) stay inline and pixel by pixel, without the run-time dispatch.
inline constexpr int kMinSimdBlockPixels = 16;
}  // namespace detail

struct BlockFragments {
  const RenderState* state = nullptr;
  const StencilOps* ops = nullptr;    // the state's ops for the triangle's facing
  const DepthPlane* plane = nullptr;  // the triangle's depth plane
  int x = 0;                          // window pixel of the block's pixel (0, 0)
  int y = 0;
  std::uint32_t* depth = nullptr;   // the block's pixel (0, 0) in the depth buffer
  std::uint8_t* stencil = nullptr;  // and in the stencil buffer
  std::ptrdiff_t stride = 0;        // values from one row to the next, in both buffers
  // Whether all 8 columns of the block lie inside the buffers' rows. Only then may a partial
  // row go through the vectors, which read every column and write the uncovered ones back
  // unchanged; at the right edge of a buffer whose width is not a multiple of 8 they would
  // reach past the row (past the buffer, on its last row).
  bool wholeColumns = false;
  // detail::compiledFragmentKernel(*state, *ops): the kernel compiled for this state, -1 for the
  // general one. -1 is always right; another index must be the state's (the caller finds it
  // once per draw, not per block).
  int kernel = -1;

  // The contract's z = (z0 + tx) + ty at pixel (c, r) of the block (DepthPlane::at).
  [[nodiscard]] double depthAt(int c, int r) const {
    return plane->at(pixelCentreFixed(x + c), pixelCentreFixed(y + r));
  }
};

// Row r's fragments one pixel at a time, for the pixels in `bits` (bit c: column c), with the
// compare functions and ops of kernel K (detail::kCompiledFragmentFuncs) or, for K = -1, the
// state's.
template <int K>
inline int applyRowFragmentsWith(const BlockFragments& b, int r, unsigned bits) {
  int applied = 0;
  std::uint32_t* depth = b.depth + r * b.stride;
  std::uint8_t* stencil = b.stencil + r * b.stride;
  while (bits != 0) {
    const int c = __builtin_ctz(bits);
    bits &= bits - 1;
    const std::uint32_t incoming = quantizeDepth(b.depthAt(c, r));
    if constexpr (K < 0) {
      applyFragment(*b.state, *b.ops, incoming, depth[c], stencil[c]);
    } else {
      constexpr detail::FragmentFuncs kFuncs = detail::kCompiledFragmentFuncs[K];
      applyFragmentWith(kFuncs.stencilFunc, kFuncs.depthFunc, kFuncs.ops, *b.state, incoming,
                        depth[c], stencil[c]);
    }
    ++applied;
  }
  return applied;
}

// The pixels of `mask` one pixel at a time with kernel K's functions (-1: the state's).
template <int K>
inline int applyBlockFragmentsScalarWith(const BlockFragments& block, std::uint64_t mask) {
  // The state, ops and plane copied into locals: every stencil store goes through a uint8_t
  // pointer, which may alias anything, so fields read through the block's pointers would be
  // loaded again after each pixel. Nothing can alias a local whose address stays here.
  const RenderState state = *block.state;
  const StencilOps ops = *block.ops;
  const DepthPlane plane = *block.plane;
  BlockFragments local = block;
  local.state = &state;
  local.ops = &ops;
  local.plane = &plane;
  int applied = 0;
  while (mask != 0) {
    const int r = __builtin_ctzll(mask) / 8;
    applied += applyRowFragmentsWith<K>(local, r, static_cast<unsigned>((mask >> (8 * r)) & 0xFF));
    mask &= ~(std::uint64_t{0xFF} << (8 * r));
  }
  return applied;
}

// Applies the fragments of the pixels whose bit (row * 8 + col) is set in `mask`, one pixel at
// a time with the state's functions (the reference the other paths are tested against); only
// those pixels are read or written. Returns how many were applied.
inline int applyBlockFragmentsScalar(const BlockFragments& block, std::uint64_t mask) {
  return applyBlockFragmentsScalarWith<-1>(block, mask);
}

namespace detail {
// One pixel at a time with the block's kernel: the compare and stencil-op switches folded to
// the pass's one case, as the SIMD kernels are.
inline int applyBlockFragmentsCompiled(const BlockFragments& block, std::uint64_t mask) {
  static_assert(kCompiledFragmentKernels == 5, "one case per compiled kernel");
  switch (block.kernel) {
    case 0:
      return applyBlockFragmentsScalarWith<0>(block, mask);
    case 1:
      return applyBlockFragmentsScalarWith<1>(block, mask);
    case 2:
      return applyBlockFragmentsScalarWith<2>(block, mask);
    case 3:
      return applyBlockFragmentsScalarWith<3>(block, mask);
    case 4:
      return applyBlockFragmentsScalarWith<4>(block, mask);
    default:
      return applyBlockFragmentsScalarWith<-1>(block, mask);
  }
}
}  // namespace detail

// The same, the denser blocks in SIMD.
inline int applyBlockFragments(const BlockFragments& block, std::uint64_t mask) {
  RECODE_INVARIANT(block.kernel == -1 ||
                       block.kernel == detail::compiledFragmentKernel(*block.state, *block.ops),
                   "a block's fragment kernel is the one compiled for its state, or the general");
  if (detail::pixelsInBlock(detail::pixelsPerRow(mask)) < detail::kMinSimdBlockPixels)
    return detail::applyBlockFragmentsCompiled(block, mask);
  return detail::applyBlockFragmentsSimd(block, mask);
}

}  // namespace recode::raster
