#include "gl_enums.hpp"

#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>

namespace recode::backends::detail {

std::uint32_t glCompareEnum(raster::CompareFunc func) {
  switch (func) {
    case raster::CompareFunc::Never:
      return GL_NEVER;
    case raster::CompareFunc::Less:
      return GL_LESS;
    case raster::CompareFunc::Equal:
      return GL_EQUAL;
    case raster::CompareFunc::LEqual:
      return GL_LEQUAL;
    case raster::CompareFunc::Greater:
      return GL_GREATER;
    case raster::CompareFunc::NotEqual:
      return GL_NOTEQUAL;
    case raster::CompareFunc::GEqual:
      return GL_GEQUAL;
    case raster::CompareFunc::Always:
      return GL_ALWAYS;
  }
  throw std::invalid_argument("GL: unknown compare function " +
                              std::to_string(static_cast<int>(func)));
}

std::uint32_t glStencilOpEnum(raster::StencilOp op) {
  switch (op) {
    case raster::StencilOp::Keep:
      return GL_KEEP;
    case raster::StencilOp::Zero:
      return GL_ZERO;
    case raster::StencilOp::Replace:
      return GL_REPLACE;
    case raster::StencilOp::Incr:
      return GL_INCR;
    case raster::StencilOp::IncrWrap:
      return GL_INCR_WRAP;
    case raster::StencilOp::Decr:
      return GL_DECR;
    case raster::StencilOp::DecrWrap:
      return GL_DECR_WRAP;
    case raster::StencilOp::Invert:
      return GL_INVERT;
  }
  throw std::invalid_argument("GL: unknown stencil op " + std::to_string(static_cast<int>(op)));
}

std::uint32_t glFaceEnum(raster::Face face) {
  switch (face) {
    case raster::Face::Front:
      return GL_FRONT;
    case raster::Face::Back:
      return GL_BACK;
    case raster::Face::Both:
      return GL_FRONT_AND_BACK;
  }
  throw std::invalid_argument("GL: unknown face " + std::to_string(static_cast<int>(face)));
}

}  // namespace recode::backends::detail
