#include "recode/raster/state.hpp"

#include <algorithm>
#include <array>

namespace recode::raster {

void RenderState::setStencilOps(Face face, const StencilOps& ops) {
  if (face != Face::Back)
    frontOps = ops;
  if (face != Face::Front)
    backOps = ops;
}

void RenderState::setScissor(const PixelRect& rect, int width, int height) {
  scissor = rect.intersect({0, 0, width, height});
}

RenderState initialRenderState(int width, int height) {
  RenderState state;
  state.scissor = {0, 0, width, height};
  return state;
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
