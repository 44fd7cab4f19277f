#pragma once
// Deliberately wrong readings of docs/rasterization.md: the mistakes an outside implementer of a
// back end is likely to make (another fill rule, another depth anchor, another order, fusion,
// precision or division of the depth plane's arithmetic, another rounding of the 24-bit depth,
// wrapping where GL saturates, ignored masks or scissor). The reference model
// (reference_model.hpp) runs any of them; the conformance kit's generator keeps only candidates
// that some variant gets wrong, and tests/raster/kit_discrimination_test.cpp proves that every
// variant fails at least kMinCatches vectors of data/golden/kit/.
//
// The depth variants are derived from the formulas of section 5, one deviation each: every
// other association of the slopes' products, sums and division, every single fusable multiply
// and add, float at each stage on its own, every other anchor, and every other rounding of the
// quantisation. Readings that give the contract's bits on every input are not listed (the
// section "What it proves" of section 9 says which and why).

#include <span>
#include <string_view>

namespace recode::kit {

enum class Variant {
  Contract,  // the contract itself
  // Coverage.
  TopLeftFill,  // left and *top* edges own their samples (D3D's rule), not bottom
  EdgeFloat,    // the edge functions evaluated in single precision
  // The plane's anchor and origin.
  AnchorRotated,           // the plane anchored at v1: built from (v1, v2, v0)
  AnchorThird,             // the plane anchored at v2: built from (v2, v0, v1)
  AnchorSorted,            // counter-clockwise order starting at the lowest (y, then x) vertex
  AnchorHighest,           // anchored at the highest (y, then lowest x) vertex
  AnchorPixelCentre,       // carried to the centre of v0's pixel, evaluated from there
  PlaneFromOrigin,         // z = (c + a X) + b Y with c the plane's value at the origin
  PlaneFromPixel00,        // carried to the centre of pixel (0, 0), evaluated from there
  IncrementalFromPixel00,  // z stepped by 256 a per column, 256 b per row from pixel (0, 0)
  // The slopes a = (dz1 e2y - dz2 e1y) / a2 (and b alike): where the division goes.
  SlopeDivideTerms,           // (dz1 e2y) / a2 - (dz2 e1y) / a2
  SlopeEdgeOverArea,          // dz1 (e2y / a2) - dz2 (e1y / a2)
  SlopeDepthOverArea,         // (dz1 / a2) e2y - (dz2 / a2) e1y
  SlopeReciprocal,            // (dz1 e2y - dz2 e1y) (1 / a2)
  SlopeReciprocalTerms,       // (dz1 e2y) (1 / a2) - (dz2 e1y) (1 / a2)
  SlopeEdgeTimesReciprocal,   // dz1 (e2y (1 / a2)) - dz2 (e1y (1 / a2))
  SlopeDepthTimesReciprocal,  // (dz1 (1 / a2)) e2y - (dz2 (1 / a2)) e1y
  // The evaluation z = (z0 + a dx) + b dy.
  EvalYFirst,           // (z0 + b dy) + a dx
  EvalOffsetsFirst,     // z0 + (a dx + b dy)
  EvalDivideSum,        // z0 + (na dx + nb dy) / a2, na and nb the slopes' numerators
  EvalDivideTerms,      // (z0 + (na dx) / a2) + (nb dy) / a2
  EvalOffsetsOverArea,  // (z0 + na (dx / a2)) + nb (dy / a2)
  Barycentric,          // (z0 + l1 dz1) + l2 dz2, lk = Ek / a2 from the exact edge functions
  BarycentricWeights,   // (l0 z0 + l1 z1) + l2 z2
  // Fused multiply-adds: all of them, or one at a time.
  FmaPlane,        // the plane's slopes and its evaluation fused with std::fma
  FmaSlopeXLeft,   // a's numerator as fma(dz1, e2y, -(dz2 e1y))
  FmaSlopeXRight,  // a's numerator as fma(-dz2, e1y, dz1 e2y)
  FmaSlopeYLeft,   // b's numerator as fma(dz2, e1x, -(dz1 e2x))
  FmaSlopeYRight,  // b's numerator as fma(-dz1, e2x, dz2 e1x)
  FmaEvalX,        // fma(a, dx, z0) + b dy
  FmaEvalY,        // fma(b, dy, z0 + a dx)
  // Single precision: everywhere, or at one stage.
  FloatPlane,         // the plane set up and evaluated in single precision
  FloatDepthInputs,   // dz1 and dz2 subtracted in float
  FloatArea,          // a2 from float products and a float difference
  FloatSlopes,        // the slopes set up in float, evaluated in double
  FloatStoredSlopes,  // the slopes set up in double, stored as floats
  FloatEvaluation,    // set up in double, evaluated in float
  FloatDepthOutput,   // the contract's z rounded to float before it is quantised
  // The 24-bit quantisation of z * 16777215.
  QuantiseHalfUp,         // floor(z * 16777215 + 0.5): ties round up, not to even
  QuantiseHalfAway,       // std::round: ties away from zero
  QuantiseHalfDown,       // ceil(z * 16777215 - 0.5): ties round down
  QuantiseTruncate,       // (uint32_t)(z * 16777215)
  QuantiseCeil,           // ceil(z * 16777215)
  QuantiseFloat,          // nearbyintf((float) z * 16777215.0f)
  QuantiseExactProduct,   // the exact product z (2^24 - 1) rounded, not its double
  Quantise2To24,          // nearbyint(z * 16777216) clamped, instead of z * 16777215
  Quantise2To24Truncate,  // (uint32_t)(z * 16777216) clamped
  // Stencil, clears, facing, validation.
  IncrWraps,                     // INCR wraps 255 to 0 instead of saturating
  DecrWraps,                     // DECR wraps 0 to 255 instead of saturating
  IgnoreValueMask,               // the stencil test compares ref with s without the value mask
  StencilClearIgnoresWriteMask,  // clear_stencil writes every bit
  DepthClearIgnoresWriteMask,    // clear_depth writes while the depth write mask is off
  ClearIgnoresScissor,           // clears fill the whole framebuffer
  SwappedFacing,                 // clockwise triangles taken as front-facing
  StrictLimits,  // validation refuses the limit values |x| or |y| = 32768 and z = 0 or 1
  // Coarser sub-pixel precision, which the graphics APIs allow (at least 4 bits): not wrong
  // readings, so the kit's vectors do not list them; subPixelVariants() lists them.
  SubPixel4Nearest,  // vertices rounded to the 1/16-pixel grid, ties to even
  SubPixel4Floor,    // vertices rounded down to the 1/16-pixel grid
  SubPixel4Ceil,     // vertices rounded up to the 1/16-pixel grid
  SubPixel4HalfUp,   // vertices rounded to the 1/16-pixel grid, ties up
  SubPixel6Nearest,  // vertices rounded to the 1/64-pixel grid, ties to even
};

struct VariantInfo {
  Variant variant;
  std::string_view name;  // e.g. "top_left_fill", as tests and the kit's descriptions name it
  std::string_view what;  // one line
};

// Every wrong variant (not Contract), in the order above.
[[nodiscard]] std::span<const VariantInfo> wrongVariants();
// The readings of a coarser sub-pixel grid (SubPixel4Nearest ...), which the APIs allow: kept
// apart from wrongVariants() so that the kit's vectors and their descriptions do not change.
[[nodiscard]] std::span<const VariantInfo> subPixelVariants();
// The name of a wrong or sub-pixel variant; "contract" for Contract.
[[nodiscard]] std::string_view variantName(Variant v);

// The kit's promise: every wrong variant fails at least this many of its vectors.
inline constexpr int kMinCatches = 3;

}  // namespace recode::kit
