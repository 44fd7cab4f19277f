#pragma once
// The device interface's names as GL enums, shared by the fixed-function and the exact GL
// device. Returned as plain integers so that this header needs no GL header (gl.h and
// glcorearb.h cannot meet in one translation unit). Each throws std::invalid_argument for a
// value outside its enum.

#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::backends::detail {

[[nodiscard]] std::uint32_t glCompareEnum(raster::CompareFunc func);
[[nodiscard]] std::uint32_t glStencilOpEnum(raster::StencilOp op);
[[nodiscard]] std::uint32_t glFaceEnum(raster::Face face);

}  // namespace recode::backends::detail
