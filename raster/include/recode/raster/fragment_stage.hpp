#pragma once
// The per-fragment stage, in GL's order: stencil test (-> sfail op), depth test (-> dpfail op),
// then dppass op and the depth write, the stencil written through its write mask
// (docs/rasterization.md, section 6). Pure functions of the state and the stored values; the
// tests hold them against a longhand model of their own (raster/kit/src/reference_model.cpp).

#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::raster {

// GL's compare and stencil-op tables. Inline: the one-pixel fragment path of every small
// triangle runs them per pixel.
[[nodiscard]] inline bool compare(CompareFunc func, std::uint32_t incoming, std::uint32_t stored) {
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

[[nodiscard]] inline std::uint8_t applyStencilOp(StencilOp op, std::uint8_t value,
                                                 std::uint8_t ref) {
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

// The bits of `updated` under the write mask, the rest of `old`: how GL writes the stencil,
// for fragments and clears alike.
[[nodiscard]] inline std::uint8_t writeThroughMask(std::uint8_t old, std::uint8_t updated,
                                                   std::uint8_t writeMask) {
  return static_cast<std::uint8_t>((updated & writeMask) |
                                   (old & static_cast<std::uint8_t>(~writeMask)));
}

// Whether the stencil test with compare function `func` passes against a stored value, under
// the state's reference and value mask.
[[nodiscard]] inline bool stencilTestPasses(CompareFunc func, const RenderState& s,
                                            std::uint8_t stored) {
  return compare(func, s.stencilRef & s.stencilValueMask, stored & s.stencilValueMask);
}

// Whether the state's stencil test passes against a stored value.
[[nodiscard]] inline bool stencilTestPasses(const RenderState& s, std::uint8_t stored) {
  return stencilTestPasses(s.stencilFunc, s, stored);
}

// applyFragment with the compare functions and ops given apart from the state (which supplies
// the references, masks and depth write): a caller that passes constants gets the tables folded
// to its one case (block_fragments.hpp compiles a kernel per pass of RECODE so).
[[gnu::always_inline]] inline void applyFragmentWith(CompareFunc stencilFunc, CompareFunc depthFunc,
                                                     const StencilOps& ops, const RenderState& s,
                                                     std::uint32_t incomingDepth,
                                                     std::uint32_t& depth, std::uint8_t& stencil) {
  const std::uint8_t old = stencil;
  StencilOp op;
  bool writeDepth = false;
  if (!stencilTestPasses(stencilFunc, s, old)) {
    op = ops.stencilFail;
  } else if (!compare(depthFunc, incomingDepth, depth)) {
    op = ops.depthFail;
  } else {
    op = ops.depthPass;
    writeDepth = s.depthWrite;
  }
  stencil = writeThroughMask(old, applyStencilOp(op, old, s.stencilRef), s.stencilWriteMask);
  if (writeDepth)
    depth = incomingDepth;
}

// Applies one fragment of depth `incomingDepth` (24-bit) to a stored depth and stencil; `ops`
// are the state's ops for the triangle's facing (RenderState::opsFor).
inline void applyFragment(const RenderState& s, const StencilOps& ops, std::uint32_t incomingDepth,
                          std::uint32_t& depth, std::uint8_t& stencil) {
  applyFragmentWith(s.stencilFunc, s.depthFunc, ops, s, incomingDepth, depth, stencil);
}

}  // namespace recode::raster
