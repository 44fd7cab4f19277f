#include "recode/kit/variants.hpp"

#include <array>

namespace recode::kit {

namespace {

constexpr std::array<VariantInfo, 18> kWrong = {{
    {Variant::TopLeftFill, "top_left_fill",
     "top-left fill rule: horizontal edges own their samples when they are top edges"},
    {Variant::AnchorRotated, "anchor_rotated",
     "depth plane anchored at the second submitted vertex (v1, v2, v0)"},
    {Variant::AnchorSorted, "anchor_sorted",
     "depth plane from the counter-clockwise order starting at the lowest vertex"},
    {Variant::FmaPlane, "fma_plane", "plane slopes and evaluation fused with std::fma"},
    {Variant::PlaneFromOrigin, "plane_from_origin",
     "plane evaluated as c + a X + b Y from the framebuffer origin"},
    {Variant::IncrementalFromPixel00, "incremental_from_pixel00",
     "depth stepped pixel by pixel from the centre of pixel (0, 0)"},
    {Variant::FloatPlane, "float_plane", "plane set up and evaluated in float"},
    {Variant::EdgeFloat, "edge_float", "edge functions evaluated in float"},
    {Variant::QuantiseHalfUp, "quantise_half_up", "depth quantisation rounds ties up"},
    {Variant::Quantise2To24, "quantise_2_24", "depth quantised as z * 16777216"},
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

}  // namespace

std::span<const VariantInfo> wrongVariants() {
  return kWrong;
}

std::string_view variantName(Variant v) {
  for (const VariantInfo& info : kWrong) {
    if (info.variant == v)
      return info.name;
  }
  return "contract";
}

}  // namespace recode::kit
