#include "recode/raster/state.hpp"

#include <algorithm>
#include <array>

namespace recode::raster {

PixelRect PixelRect::intersect(const PixelRect& o) const {
  PixelRect r{std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  if (r.x1 < r.x0)
    r.x1 = r.x0;
  if (r.y1 < r.y0)
    r.y1 = r.y0;
  return r;
}

bool compare(CompareFunc func, std::uint32_t incoming, std::uint32_t stored) {
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

std::uint8_t applyStencilOp(StencilOp op, std::uint8_t value, std::uint8_t ref) {
  switch (op) {
    case StencilOp::Keep:
      return value;
    case StencilOp::Zero:
      return 0;
    case StencilOp::Replace:
      return ref;
    case StencilOp::Incr:
      return value == 0xFF ? value : static_cast<std::uint8_t>(value + 1);
    case StencilOp::IncrWrap:
      return static_cast<std::uint8_t>(value + 1);
    case StencilOp::Decr:
      return value == 0 ? value : static_cast<std::uint8_t>(value - 1);
    case StencilOp::DecrWrap:
      return static_cast<std::uint8_t>(value - 1);
    case StencilOp::Invert:
      return static_cast<std::uint8_t>(~value);
  }
  return value;
}

namespace {

constexpr std::array<std::string_view, 8> kCompareNames = {
    "NEVER", "LESS", "EQUAL", "LEQUAL", "GREATER", "NOTEQUAL", "GEQUAL", "ALWAYS"};
constexpr std::array<std::string_view, 8> kStencilOpNames = {
    "KEEP", "ZERO", "REPLACE", "INCR", "INCR_WRAP", "DECR", "DECR_WRAP", "INVERT"};
constexpr std::array<std::string_view, 3> kFaceNames = {"front", "back", "both"};
constexpr std::array<std::string_view, 3> kCullNames = {"none", "front", "back"};

template <class Enum, std::size_t N>
std::optional<Enum> parseName(const std::array<std::string_view, N>& names, std::string_view s) {
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i] == s)
      return static_cast<Enum>(i);
  }
  return std::nullopt;
}

}  // namespace

std::string_view toString(CompareFunc f) {
  return kCompareNames.at(static_cast<std::size_t>(f));
}
std::string_view toString(StencilOp op) {
  return kStencilOpNames.at(static_cast<std::size_t>(op));
}
std::string_view toString(Face face) {
  return kFaceNames.at(static_cast<std::size_t>(face));
}
std::string_view toString(CullMode mode) {
  return kCullNames.at(static_cast<std::size_t>(mode));
}

std::optional<CompareFunc> parseCompareFunc(std::string_view s) {
  return parseName<CompareFunc>(kCompareNames, s);
}
std::optional<StencilOp> parseStencilOp(std::string_view s) {
  return parseName<StencilOp>(kStencilOpNames, s);
}
std::optional<Face> parseFace(std::string_view s) {
  return parseName<Face>(kFaceNames, s);
}
std::optional<CullMode> parseCullMode(std::string_view s) {
  return parseName<CullMode>(kCullNames, s);
}

}  // namespace recode::raster
