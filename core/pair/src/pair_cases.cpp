#include "recode/pair/pair_cases.hpp"

#include <algorithm>
#include <array>

namespace recode::core {

int caseFromIntervals(const std::optional<DepthInterval>& a,
                      const std::optional<DepthInterval>& b) {
  if (!a)
    return b ? 8 : 0;
  if (!b)
    return 1;
  const std::uint32_t amin = std::min(a->min, a->max), amax = std::max(a->min, a->max);
  const std::uint32_t bmin = std::min(b->min, b->max), bmax = std::max(b->min, b->max);
  if (amax < bmin)
    return 2;
  if (bmax < amin)
    return 7;
  // The intervals share a value from here on.
  if (amin <= bmin)
    return bmax <= amax ? 5 : 3;
  return bmax <= amax ? 6 : 4;
}

int caseFromStencil(std::uint8_t stencil) {
  const int count = stencil & kCountBits;
  const bool front = (stencil & kFrontBehindAminBit) != 0;
  const bool back = (stencil & kBackBehindAminBit) != 0;
  switch (count) {
    case 0:  // A absent: bits 2 and 3 were set by B's faces failing the "A present" test.
      return front || back ? 8 : 0;
    case 1:  // A present, no face of B at or before Amax.
      return front || back ? 2 : 1;
    case 2:  // Bmin <= Amax < Bmax: B's near end decides between 3 and 4.
      return front && back ? 3 : 4;
    default:  // Both faces of B at or before Amax.
      if (front && back)
        return 5;
      return front || back ? 6 : 7;
  }
}

std::string_view caseName(int pixelCase) {
  static constexpr std::array<std::string_view, kCaseCount> kNames = {
      "neither block",
      "A only",
      "B behind A",
      "B enters A from behind",
      "B spans A",
      "A spans B",
      "B enters A from the front",
      "B in front of A",
      "B only",
  };
  if (pixelCase < 0 || pixelCase >= kCaseCount)
    return "invalid case";
  return kNames[static_cast<std::size_t>(pixelCase)];
}

}  // namespace recode::core
