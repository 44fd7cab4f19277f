#include "vulkan_enums.hpp"

#include <stdexcept>
#include <string>

namespace recode::backends::detail {

VkCompareOp vkCompareOp(raster::CompareFunc func) {
  switch (func) {
    case raster::CompareFunc::Never:
      return VK_COMPARE_OP_NEVER;
    case raster::CompareFunc::Less:
      return VK_COMPARE_OP_LESS;
    case raster::CompareFunc::Equal:
      return VK_COMPARE_OP_EQUAL;
    case raster::CompareFunc::LEqual:
      return VK_COMPARE_OP_LESS_OR_EQUAL;
    case raster::CompareFunc::Greater:
      return VK_COMPARE_OP_GREATER;
    case raster::CompareFunc::NotEqual:
      return VK_COMPARE_OP_NOT_EQUAL;
    case raster::CompareFunc::GEqual:
      return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case raster::CompareFunc::Always:
      return VK_COMPARE_OP_ALWAYS;
  }
  throw std::invalid_argument("Vulkan: unknown compare function " +
                              std::to_string(static_cast<int>(func)));
}

// GL's INCR and DECR saturate, as Vulkan's *_AND_CLAMP do; INCR_WRAP and DECR_WRAP wrap.
VkStencilOp vkStencilOp(raster::StencilOp op) {
  switch (op) {
    case raster::StencilOp::Keep:
      return VK_STENCIL_OP_KEEP;
    case raster::StencilOp::Zero:
      return VK_STENCIL_OP_ZERO;
    case raster::StencilOp::Replace:
      return VK_STENCIL_OP_REPLACE;
    case raster::StencilOp::Incr:
      return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
    case raster::StencilOp::IncrWrap:
      return VK_STENCIL_OP_INCREMENT_AND_WRAP;
    case raster::StencilOp::Decr:
      return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
    case raster::StencilOp::DecrWrap:
      return VK_STENCIL_OP_DECREMENT_AND_WRAP;
    case raster::StencilOp::Invert:
      return VK_STENCIL_OP_INVERT;
  }
  throw std::invalid_argument("Vulkan: unknown stencil op " + std::to_string(static_cast<int>(op)));
}

}  // namespace recode::backends::detail
