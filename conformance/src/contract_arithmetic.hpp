#pragma once
// The contract's exact arithmetic and checks that the conformance library's own readings of it
// share (pixel_history.cpp, api_freedoms.cpp): the frame size and a draw's validation, snapping
// and rounding half to even, the compare functions, the stencil ops and the write mask, written
// from docs/rasterization.md sections 1, 2, 5 and 6. The kit's reference model keeps its own, so
// that it stays an independent reading.

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "recode/raster/command_stream.hpp"
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

inline constexpr std::uint32_t kDepthOne = 16777215u;  // 2^24 - 1: the far plane, 24 bits
inline constexpr int kMaxSize = 16384;                 // section 1: frames of 1..16384 pixels
inline constexpr double kMaxCoordinate = 32768.0;      // section 2: |x|, |y| <= 2^15 pixels

// Section 1: a frame of 1..16384 pixels a side. `who` names the caller in the message.
inline void checkFrameSize(std::string_view who, int width, int height) {
  if (width < 1 || width > kMaxSize || height < 1 || height > kMaxSize)
    throw std::invalid_argument(std::string(who) + ": frame size " + std::to_string(width) + " x " +
                                std::to_string(height) + " outside 1..16384");
}

// Section 2: the whole draw is validated before anything is drawn: whole triangles, indices in
// range, finite vertices within |x|, |y| <= 32768 and depths in [0, 1]. Throws
// std::invalid_argument naming `who` and the command.
inline void validateDraw(std::string_view who, const raster::cmd::Draw& draw, int command) {
  const std::string where = std::string(who) + ": command " + std::to_string(command) + ": ";
  if (draw.indices.size() % 3 != 0)
    throw std::invalid_argument(where + "index count is not a multiple of 3");
  for (std::size_t k = 0; k < draw.indices.size(); ++k) {
    const std::uint32_t i = draw.indices[k];
    if (static_cast<std::size_t>(i) >= draw.vertices.size())
      throw std::invalid_argument(where + "index " + std::to_string(k) + " is out of range");
    const raster::WindowVertex& v = draw.vertices[i];
    const double x = static_cast<double>(v.x);
    const double y = static_cast<double>(v.y);
    const double z = static_cast<double>(v.z);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw std::invalid_argument(where + "vertex " + std::to_string(i) + " is not finite");
    if (std::fabs(x) > kMaxCoordinate || std::fabs(y) > kMaxCoordinate)
      throw std::invalid_argument(where + "vertex " + std::to_string(i) +
                                  " lies outside |x|, |y| <= 32768");
    if (!(z >= 0.0 && z <= 1.0))
      throw std::invalid_argument(where + "vertex " + std::to_string(i) +
                                  " has a depth outside [0, 1]");
  }
}

// Section 2: X = nearbyint(x * 256) in double, on the 24.8 grid.
inline long long snap(float v) {
  return static_cast<long long>(roundHalfEven(static_cast<double>(v) * 256.0));
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
