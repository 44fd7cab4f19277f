#pragma once
// Sub-pixel snapping and depth quantisation: the two places where real numbers become the
// integers that every back end must agree on (docs/rasterization.md, sections 2 and 5).

#include <cmath>
#include <cstdint>

#if defined(__x86_64__) && defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "recode/raster/state.hpp"

namespace recode::raster {

// Window coordinate -> 24.8 fixed point, round half to even. Exact for |x| < 65536 because
// multiplying a float by 256 only changes its exponent.
// On x86-64 one cvtsd2si, which rounds with the current rounding mode as nearbyint does (round
// half to even by default) and gives nearbyint's integer for every result in the int64 range;
// the libm call it replaces ran six times for every triangle of a draw.
[[nodiscard]] inline std::int64_t snapToFixed(float x) {
  const double scaled = static_cast<double>(x) * kSubpixelOne;
#if defined(__x86_64__) && defined(__SSE2__)
  return _mm_cvtsd_si64(_mm_set_sd(scaled));
#else
  return static_cast<std::int64_t>(std::nearbyint(scaled));
#endif
}

// The value a pre-snapping producer should hand to the device: x on the 1/256-pixel grid.
[[nodiscard]] inline float snapToSubpixel(double x) {
  return static_cast<float>(std::nearbyint(x * kSubpixelOne) / kSubpixelOne);
}

// Floor division by a positive divisor, correct for negative numerators: the block spans of
// the traversal round with it.
[[nodiscard]] inline std::int64_t floorDiv(std::int64_t n, std::int64_t d) {
  std::int64_t q = n / d;
  if ((n % d != 0) && (n < 0))
    --q;
  return q;
}

// The first and last pixel whose centre 256 i + 128 lies in [lo, hi] (24.8 fixed point):
// ceil((lo - 128) / 256) and floor((hi - 128) / 256), the candidate pixels of a triangle's box.
// An arithmetic shift right floors, so these are floorDiv's values without its branches.
[[nodiscard]] inline std::int64_t firstPixelCentreFrom(std::int64_t lo) {
  return -((kSubpixelOne / 2 - lo) >> kSubpixelBits);
}
[[nodiscard]] inline std::int64_t lastPixelCentreTo(std::int64_t hi) {
  return (hi - kSubpixelOne / 2) >> kSubpixelBits;
}

// Fixed-point coordinate of the centre of pixel column/row i: 256 i + 128.
[[nodiscard]] inline std::int64_t pixelCentreFixed(int i) {
  return static_cast<std::int64_t>(i) * kSubpixelOne + kSubpixelOne / 2;
}

// Adding and subtracting 1.5 * 2^52 rounds a double in [0, 2^51) to an integer with the
// current rounding mode (round half to even by default), exactly like std::nearbyint but
// without a libm call on x86-64 targets that lack SSE4.1 roundsd. quantizeDepth and its SIMD
// twin (block_fragments.cpp) both round with it.
inline constexpr double kRoundToIntegerBias = 6755399441055744.0;

// Depth in [0, 1] (clamped; NaN is treated as 0) -> 24-bit unorm, round(z * (2^24 - 1)) with
// round half to even, evaluated in double.
[[nodiscard]] inline std::uint32_t quantizeDepth(double z) {
  if (!(z > 0.0))
    return 0;
  if (z >= 1.0)
    return kDepthMax;
  const double scaled = z * static_cast<double>(kDepthMax);
  return static_cast<std::uint32_t>((scaled + kRoundToIntegerBias) - kRoundToIntegerBias);
}

}  // namespace recode::raster
