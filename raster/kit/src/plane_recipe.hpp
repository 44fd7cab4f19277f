#pragma once
// How the reference model computes a fragment's depth under each variant: the contract's
// section 5 taken apart into its choices (anchor, where the evaluation starts, where the
// slopes' division goes, the order of the evaluation, which multiply-adds are fused, which
// stages run in float, and the rounding of the quantisation). Each wrong depth variant changes
// exactly one of them (fma_plane and float_plane several), so ModelPlane implements the choices
// once and every variant is a row of planeRecipe.

#include "recode/kit/variants.hpp"

namespace recode::kit::detail {

// The vertex the plane is anchored at; the other two follow in submitted (cyclic) order.
enum class AnchorVertex { First, Second, Third, Lowest, Highest };

// The point the evaluation starts from: the anchor vertex, or a point the plane is carried to
// first (its value there computed as the contract evaluates it), or pixel (0, 0) stepped from.
enum class PlaneOrigin {
  Anchor,
  AnchorPixelCentre,
  FramebufferOrigin,
  Pixel00,
  SteppedFromPixel00
};

// a = (dz1 e2y - dz2 e1y) / a2 (b alike), with r = 1 / a2.
enum class SlopeForm {
  DivideNumerator,       // (dz1 e2y - dz2 e1y) / a2: the contract
  DivideTerms,           // (dz1 e2y) / a2 - (dz2 e1y) / a2
  EdgeOverArea,          // dz1 (e2y / a2) - dz2 (e1y / a2)
  DepthOverArea,         // (dz1 / a2) e2y - (dz2 / a2) e1y
  Reciprocal,            // (dz1 e2y - dz2 e1y) r
  ReciprocalTerms,       // (dz1 e2y) r - (dz2 e1y) r
  EdgeTimesReciprocal,   // dz1 (e2y r) - dz2 (e1y r)
  DepthTimesReciprocal,  // (dz1 r) e2y - (dz2 r) e1y
};

// z at a sample dx, dy from the origin; na, nb are the slopes' numerators.
enum class EvalForm {
  XThenY,              // (z0 + a dx) + b dy: the contract
  YThenX,              // (z0 + b dy) + a dx
  OffsetsFirst,        // z0 + (a dx + b dy)
  DivideSum,           // z0 + (na dx + nb dy) / a2
  DivideTerms,         // (z0 + (na dx) / a2) + (nb dy) / a2
  OffsetsOverArea,     // (z0 + na (dx / a2)) + nb (dy / a2)
  Barycentric,         // (z0 + l1 dz1) + l2 dz2 with lk = Ek / a2, Ek exact integers
  BarycentricWeights,  // (l0 z0 + l1 z1) + l2 z2
};

// Which multiply-adds std::fma fuses (bit flags).
inline constexpr unsigned kFuseSlopeXLeft = 1;   // fma(dz1, e2y, -(dz2 e1y))
inline constexpr unsigned kFuseSlopeXRight = 2;  // fma(-dz2, e1y, dz1 e2y)
inline constexpr unsigned kFuseSlopeYLeft = 4;   // fma(dz2, e1x, -(dz1 e2x))
inline constexpr unsigned kFuseSlopeYRight = 8;  // fma(-dz1, e2x, dz2 e1x)
inline constexpr unsigned kFuseEvalX = 16;       // fma(a, dx, z0)
inline constexpr unsigned kFuseEvalY = 32;       // fma(b, dy, z0 + a dx)

// Which stages run in float (bit flags).
inline constexpr unsigned kFloatDepthInputs = 1;   // dz1 = v1.z - v0.z subtracted in float
inline constexpr unsigned kFloatArea = 2;          // a2 from float products and difference
inline constexpr unsigned kFloatSetup = 4;         // the whole setup, slopes included, in float
inline constexpr unsigned kFloatStoredSlopes = 8;  // double slopes rounded to float
inline constexpr unsigned kFloatEvaluation = 16;   // z0 + a dx + b dy in float
inline constexpr unsigned kFloatOutput = 32;       // z rounded to float before quantisation

struct PlaneRecipe {
  AnchorVertex anchor = AnchorVertex::First;
  PlaneOrigin origin = PlaneOrigin::Anchor;
  SlopeForm slopes = SlopeForm::DivideNumerator;
  EvalForm eval = EvalForm::XThenY;
  unsigned fused = 0;
  unsigned inFloat = 0;
};

// The 24-bit quantisation of z in (0, 1); outside, every rounding clamps as the contract does.
enum class Rounding {
  NearestEven,         // nearbyint(z * 16777215): the contract
  HalfUp,              // floor(z * 16777215 + 0.5)
  HalfAway,            // round(z * 16777215)
  HalfDown,            // ceil(z * 16777215 - 0.5)
  Truncate,            // floor(z * 16777215)
  Ceil,                // ceil(z * 16777215)
  FloatMultiply,       // nearbyintf((float) z * 16777215.0f)
  ExactProduct,        // the exact z (2^24 - 1) rounded half to even
  Scale2To24,          // min(nearbyint(z * 16777216), 16777215)
  Scale2To24Truncate,  // min(floor(z * 16777216), 16777215)
};

// The contract's recipe for Contract and for every variant that is not about depth.
[[nodiscard]] PlaneRecipe planeRecipe(Variant v);
[[nodiscard]] Rounding rounding(Variant v);

}  // namespace recode::kit::detail
