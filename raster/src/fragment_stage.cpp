// The per-fragment stage's tables: GL's compare functions and stencil ops.
#include "recode/raster/fragment_stage.hpp"

namespace recode::raster {

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

}  // namespace recode::raster
