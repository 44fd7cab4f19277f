#pragma once
// Deliberately wrong readings of docs/rasterization.md: the mistakes an outside implementer of a
// back end is likely to make (another fill rule, another depth anchor, fused or float
// arithmetic, another rounding, wrapping where GL saturates, ignored masks or scissor). The
// reference model (reference_model.hpp) runs any of them; the conformance kit's generator keeps
// only candidates that some variant gets wrong, and tests/raster/kit_discrimination_test.cpp
// proves that every variant fails at least one vector of data/golden/kit/.

#include <span>
#include <string_view>

namespace recode::kit {

enum class Variant {
  Contract,                // the contract itself
  TopLeftFill,             // left and *top* edges own their samples (D3D's rule), not bottom
  AnchorRotated,           // the plane anchored at v1: built from (v1, v2, v0)
  AnchorSorted,            // counter-clockwise order starting at the lowest (y, then x) vertex
  FmaPlane,                // the plane's slopes and its evaluation fused with std::fma
  PlaneFromOrigin,         // z = (c + a X) + b Y with c the plane's value at the origin
  IncrementalFromPixel00,  // z stepped by 256 a per column, 256 b per row from pixel (0, 0)
  FloatPlane,              // the plane set up and evaluated in single precision
  EdgeFloat,               // the edge functions evaluated in single precision
  QuantiseHalfUp,          // floor(z * 16777215 + 0.5): ties round up, not to even
  Quantise2To24,           // nearbyint(z * 16777216) clamped, instead of z * 16777215
  IncrWraps,               // INCR wraps 255 to 0 instead of saturating
  DecrWraps,               // DECR wraps 0 to 255 instead of saturating
  IgnoreValueMask,         // the stencil test compares ref with s without the value mask
  StencilClearIgnoresWriteMask,  // clear_stencil writes every bit
  DepthClearIgnoresWriteMask,    // clear_depth writes while the depth write mask is off
  ClearIgnoresScissor,           // clears fill the whole framebuffer
  SwappedFacing,                 // clockwise triangles taken as front-facing
  StrictLimits,  // validation refuses the limit values |x| or |y| = 32768 and z = 0 or 1
};

struct VariantInfo {
  Variant variant;
  std::string_view name;  // e.g. "top_left_fill", as tests and the kit's descriptions name it
  std::string_view what;  // one line
};

// Every wrong variant (not Contract), in the order above.
[[nodiscard]] std::span<const VariantInfo> wrongVariants();
[[nodiscard]] std::string_view variantName(Variant v);

}  // namespace recode::kit
