#pragma once
// The contract's exact arithmetic that the conformance library's own readings of it share
// (pixel_history.cpp, api_freedoms.cpp): rounding half to even, the compare functions, the
// stencil ops and the write mask, written from docs/rasterization.md sections 2, 5 and 6. The
// kit's reference model keeps its own, so that it stays an independent reading.

#include <cmath>
#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::conformance::contract {

using raster::CompareFunc;
using raster::StencilOp;

// Round half to even, written out so that it does not depend on the floating-point
// environment's rounding mode (nearbyint in the default mode gives the same). Used for the
// snapping (section 2) and the quantisation (section 5); `v - floor(v)` is exact in double.
inline double roundHalfEven(double v) {
  const double k = std::floor(v);
  const double frac = v - k;
  if (frac > 0.5)
    return k + 1.0;
  if (frac < 0.5)
    return k;
  return std::fmod(k, 2.0) == 0.0 ? k : k + 1.0;
}

// Section 6: `incoming FUNC stored`.
inline bool compare(CompareFunc func, std::uint32_t incoming, std::uint32_t stored) {
  switch (func) {
    case CompareFunc::Never:
      return false;
    case CompareFunc::Less:
      return incoming < stored;
    case CompareFunc::Equal:
      return incoming == stored;
    case CompareFunc::LEqual:
      return incoming <= stored;
    case CompareFunc::Greater:
      return incoming > stored;
    case CompareFunc::NotEqual:
      return incoming != stored;
    case CompareFunc::GEqual:
      return incoming >= stored;
    case CompareFunc::Always:
      return true;
  }
  return false;
}

// Section 6's stencil ops on 8 bits.
inline std::uint8_t applyOp(StencilOp op, std::uint8_t s, std::uint8_t ref) {
  switch (op) {
    case StencilOp::Keep:
      return s;
    case StencilOp::Zero:
      return 0;
    case StencilOp::Replace:
      return ref;
    case StencilOp::Incr:
      return s == 255 ? s : static_cast<std::uint8_t>(s + 1);
    case StencilOp::IncrWrap:
      return static_cast<std::uint8_t>((s + 1) % 256);
    case StencilOp::Decr:
      return s == 0 ? s : static_cast<std::uint8_t>(s - 1);
    case StencilOp::DecrWrap:
      return static_cast<std::uint8_t>((s + 255) % 256);
    case StencilOp::Invert:
      return static_cast<std::uint8_t>(255 - s);
  }
  return s;
}

// s <- (n & writeMask) | (s & ~writeMask)
inline std::uint8_t masked(std::uint8_t n, std::uint8_t s, std::uint8_t writeMask) {
  return static_cast<std::uint8_t>((n & writeMask) | (s & static_cast<std::uint8_t>(~writeMask)));
}

}  // namespace recode::conformance::contract
