#pragma once
// The per-fragment stage, in GL's order: stencil test (-> sfail op), depth test
// (-> dpfail op), then dppass op and the depth write (docs/rasterization.md, section 6).

#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::raster {

struct DepthStencilState {
  CompareFunc depthFunc = CompareFunc::Less;  // GL defaults
  bool depthWrite = true;
  CompareFunc stencilFunc = CompareFunc::Always;
  std::uint8_t stencilRef = 0;
  std::uint8_t stencilValueMask = 0xFF;
  std::uint8_t stencilWriteMask = 0xFF;
  StencilOps frontOps;
  StencilOps backOps;
  CullMode cull = CullMode::None;
};

// Applies one fragment of depth `incomingDepth` (24-bit) to a stored depth and stencil.
inline void applyFragment(const DepthStencilState& s, const StencilOps& ops,
                          std::uint32_t incomingDepth, std::uint32_t& depth,
                          std::uint8_t& stencil) {
  const std::uint8_t old = stencil;
  StencilOp op;
  bool writeDepth = false;
  if (!compare(s.stencilFunc, s.stencilRef & s.stencilValueMask, old & s.stencilValueMask)) {
    op = ops.stencilFail;
  } else if (!compare(s.depthFunc, incomingDepth, depth)) {
    op = ops.depthFail;
  } else {
    op = ops.depthPass;
    writeDepth = s.depthWrite;
  }
  const std::uint8_t updated = applyStencilOp(op, old, s.stencilRef);
  stencil = static_cast<std::uint8_t>((updated & s.stencilWriteMask) |
                                      (old & static_cast<std::uint8_t>(~s.stencilWriteMask)));
  if (writeDepth)
    depth = incomingDepth;
}

}  // namespace recode::raster
