#pragma once
// The nine per-pixel cases of RECODE for convex blocks A, B (docs/algorithm.md section 1)
// and the stencil encoding the pair algorithm leaves behind (docs/algorithm.md, "Stencil
// encoding"). Back-end authors decode their own stencil read-back with caseFromStencil().

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace recode::core {

inline constexpr int kCaseCount = 9;

// Closed depth intervals along the view ray at one pixel, as 24-bit depth values (smaller
// is nearer the viewer). nullopt: the block does not cover the pixel.
struct DepthInterval {
  std::uint32_t min = 0;  // nearest boundary (entry)
  std::uint32_t max = 0;  // farthest boundary (exit)
  friend bool operator==(const DepthInterval&, const DepthInterval&) = default;
};

// The case table from the intervals themselves, the definition the stencil encoding is
// checked against:
//   0 neither, 1 A only, 8 B only,
//   2 Amax < Bmin, 3 Amin <= Bmin <= Amax < Bmax, 4 Bmin < Amin and Amax < Bmax,
//   5 Amin <= Bmin and Bmax <= Amax, 6 Bmin < Amin <= Bmax <= Amax, 7 Bmax < Amin.
// An interval whose min exceeds its max is taken with its ends swapped.
[[nodiscard]] int caseFromIntervals(const std::optional<DepthInterval>& a,
                                    const std::optional<DepthInterval>& b);

// Cases 3-6: the intervals share at least one depth value (touching counts).
[[nodiscard]] constexpr bool isInterfering(int pixelCase) {
  return pixelCase >= 3 && pixelCase <= 6;
}

// Stencil bits after the pair algorithm's passes:
//   bits 0-1  the paper's count: 0 outside A, else 1 + faces of B at or before Amax
//   bit 2     B's front face at or behind Amin, or B present where A is absent
//   bit 3     B's back face at or behind Amin, or B present where A is absent
inline constexpr std::uint8_t kCountBits = 0x03;
inline constexpr std::uint8_t kFrontBehindAminBit = 0x04;
inline constexpr std::uint8_t kBackBehindAminBit = 0x08;
inline constexpr std::uint8_t kUsedStencilBits = 0x0F;

// The case of a pixel from its final stencil value (only the bits above are looked at).
[[nodiscard]] int caseFromStencil(std::uint8_t stencil);

// Short names for messages and legends: "neither", "A only", "B behind A", ...
[[nodiscard]] std::string_view caseName(int pixelCase);

}  // namespace recode::core
