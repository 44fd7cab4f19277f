#include "recode/kit/variants.hpp"

#include <array>
#include <cstddef>

namespace recode::kit {

namespace {

constexpr std::array<VariantInfo, 55> kWrong = {{
    {Variant::TopLeftFill, "top_left_fill",
     "top-left fill rule: horizontal edges own their samples when they are top edges"},
    {Variant::EdgeFloat, "edge_float", "edge functions evaluated in float"},
    {Variant::AnchorRotated, "anchor_rotated",
     "depth plane anchored at the second submitted vertex (v1, v2, v0)"},
    {Variant::AnchorThird, "anchor_third",
     "depth plane anchored at the third submitted vertex (v2, v0, v1)"},
    {Variant::AnchorSorted, "anchor_sorted",
     "depth plane from the counter-clockwise order starting at the lowest vertex"},
    {Variant::AnchorHighest, "anchor_highest", "depth plane anchored at the highest vertex"},
    {Variant::AnchorPixelCentre, "anchor_pixel_centre",
     "plane carried to the centre of v0's pixel and evaluated from there"},
    {Variant::PlaneFromOrigin, "plane_from_origin",
     "plane evaluated as c + a X + b Y from the framebuffer origin"},
    {Variant::PlaneFromPixel00, "plane_from_pixel00",
     "plane carried to the centre of pixel (0, 0) and evaluated from there"},
    {Variant::IncrementalFromPixel00, "incremental_from_pixel00",
     "depth stepped pixel by pixel from the centre of pixel (0, 0)"},
    {Variant::SlopeDivideTerms, "slope_divide_terms",
     "slopes divide each product by the area: (dz1 e2y) / a2 - (dz2 e1y) / a2"},
    {Variant::SlopeEdgeOverArea, "slope_edge_over_area",
     "slopes as dz1 (e2y / a2) - dz2 (e1y / a2)"},
    {Variant::SlopeDepthOverArea, "slope_depth_over_area",
     "slopes as (dz1 / a2) e2y - (dz2 / a2) e1y"},
    {Variant::SlopeReciprocal, "slope_reciprocal",
     "slopes multiply the numerator by 1 / a2 instead of dividing"},
    {Variant::SlopeReciprocalTerms, "slope_reciprocal_terms",
     "slopes as (dz1 e2y) (1 / a2) - (dz2 e1y) (1 / a2)"},
    {Variant::SlopeEdgeTimesReciprocal, "slope_edge_times_reciprocal",
     "slopes as dz1 (e2y (1 / a2)) - dz2 (e1y (1 / a2))"},
    {Variant::SlopeDepthTimesReciprocal, "slope_depth_times_reciprocal",
     "slopes as (dz1 (1 / a2)) e2y - (dz2 (1 / a2)) e1y"},
    {Variant::EvalYFirst, "eval_y_first", "plane evaluated as (z0 + ty) + tx"},
    {Variant::EvalOffsetsFirst, "eval_offsets_first", "plane evaluated as z0 + (tx + ty)"},
    {Variant::EvalDivideSum, "eval_divide_sum",
     "slopes' numerators kept, plane evaluated as z0 + (na dx + nb dy) / a2"},
    {Variant::EvalDivideTerms, "eval_divide_terms",
     "slopes' numerators kept, plane evaluated as (z0 + (na dx) / a2) + (nb dy) / a2"},
    {Variant::EvalOffsetsOverArea, "eval_offsets_over_area",
     "slopes' numerators kept, plane evaluated as (z0 + na (dx / a2)) + nb (dy / a2)"},
    {Variant::Barycentric, "barycentric",
     "depth as (z0 + l1 dz1) + l2 dz2 from barycentrics lk = Ek / a2"},
    {Variant::BarycentricWeights, "barycentric_weights",
     "depth as (l0 z0 + l1 z1) + l2 z2 from barycentrics lk = Ek / a2"},
    {Variant::FmaPlane, "fma_plane", "plane slopes and evaluation fused with std::fma"},
    {Variant::FmaSlopeXLeft, "fma_slope_x_left",
     "x slope's numerator fused as fma(dz1, e2y, -(dz2 e1y))"},
    {Variant::FmaSlopeXRight, "fma_slope_x_right",
     "x slope's numerator fused as fma(-dz2, e1y, dz1 e2y)"},
    {Variant::FmaSlopeYLeft, "fma_slope_y_left",
     "y slope's numerator fused as fma(dz2, e1x, -(dz1 e2x))"},
    {Variant::FmaSlopeYRight, "fma_slope_y_right",
     "y slope's numerator fused as fma(-dz1, e2x, dz2 e1x)"},
    {Variant::FmaEvalX, "fma_eval_x", "plane evaluated as fma(a, dx, z0) + ty"},
    {Variant::FmaEvalY, "fma_eval_y", "plane evaluated as fma(b, dy, z0 + tx)"},
    {Variant::FloatPlane, "float_plane", "plane set up and evaluated in float"},
    {Variant::FloatDepthInputs, "float_depth_inputs", "depth differences dz1, dz2 taken in float"},
    {Variant::FloatArea, "float_area", "plane's area a2 computed in float"},
    {Variant::FloatSlopes, "float_slopes", "slopes set up in float, plane evaluated in double"},
    {Variant::FloatStoredSlopes, "float_stored_slopes",
     "slopes set up in double and stored as floats"},
    {Variant::FloatEvaluation, "float_evaluation", "plane set up in double, evaluated in float"},
    {Variant::FloatDepthOutput, "float_depth_output",
     "interpolated depth rounded to float before quantisation"},
    {Variant::QuantiseHalfUp, "quantise_half_up", "depth quantisation rounds ties up"},
    {Variant::QuantiseHalfAway, "quantise_half_away",
     "depth quantisation rounds ties away from zero (std::round)"},
    {Variant::QuantiseHalfDown, "quantise_half_down", "depth quantisation rounds ties down"},
    {Variant::QuantiseTruncate, "quantise_truncate", "depth quantisation truncates"},
    {Variant::QuantiseCeil, "quantise_ceil", "depth quantisation rounds up"},
    {Variant::QuantiseFloat, "quantise_float", "depth quantisation multiplies in float"},
    {Variant::QuantiseExactProduct, "quantise_exact_product",
     "depth quantisation rounds the exact product z (2^24 - 1), not its double"},
    {Variant::Quantise2To24, "quantise_2_24", "depth quantised as z * 16777216"},
    {Variant::Quantise2To24Truncate, "quantise_2_24_truncate",
     "depth quantised as z * 16777216 truncated"},
    {Variant::IncrWraps, "incr_wraps", "INCR wraps at 255 instead of saturating"},
    {Variant::DecrWraps, "decr_wraps", "DECR wraps at 0 instead of saturating"},
    {Variant::IgnoreValueMask, "ignore_value_mask", "stencil test without the value mask"},
    {Variant::StencilClearIgnoresWriteMask, "stencil_clear_ignores_write_mask",
     "clear_stencil ignores the stencil write mask"},
    {Variant::DepthClearIgnoresWriteMask, "depth_clear_ignores_write_mask",
     "clear_depth ignores the depth write mask"},
    {Variant::ClearIgnoresScissor, "clear_ignores_scissor", "clears ignore the scissor"},
    {Variant::SwappedFacing, "swapped_facing", "clockwise triangles taken as front-facing"},
    {Variant::StrictLimits, "strict_limits",
     "validation refuses |x|, |y| = 32768 and z = 0 or 1, which the contract accepts"},
}};

// The table lists every wrong variant once, in the enumeration's order, so that a variant added
// to the enumeration and forgotten here stops the build instead of escaping the kit's test.
constexpr bool inEnumerationOrder() {
  for (std::size_t i = 0; i < kWrong.size(); ++i) {
    if (kWrong[i].variant != static_cast<Variant>(i + 1))
      return false;
  }
  return true;
}
static_assert(inEnumerationOrder() &&
              static_cast<int>(Variant::StrictLimits) == static_cast<int>(kWrong.size()));

constexpr std::array<VariantInfo, 5> kSubPixel = {{
    {Variant::SubPixel4Nearest, "subpixel_4_nearest",
     "vertices rounded to 4 sub-pixel bits (1/16 pixel), ties to even"},
    {Variant::SubPixel4Floor, "subpixel_4_floor", "vertices rounded down to 4 sub-pixel bits"},
    {Variant::SubPixel4Ceil, "subpixel_4_ceil", "vertices rounded up to 4 sub-pixel bits"},
    {Variant::SubPixel4HalfUp, "subpixel_4_half_up",
     "vertices rounded to 4 sub-pixel bits, ties up"},
    {Variant::SubPixel6Nearest, "subpixel_6_nearest",
     "vertices rounded to 6 sub-pixel bits (1/64 pixel), ties to even"},
}};

}  // namespace

std::span<const VariantInfo> wrongVariants() {
  return kWrong;
}

std::span<const VariantInfo> subPixelVariants() {
  return kSubPixel;
}

std::string_view variantName(Variant v) {
  for (const VariantInfo& info : kWrong) {
    if (info.variant == v)
      return info.name;
  }
  for (const VariantInfo& info : kSubPixel) {
    if (info.variant == v)
      return info.name;
  }
  return "contract";
}

}  // namespace recode::kit
