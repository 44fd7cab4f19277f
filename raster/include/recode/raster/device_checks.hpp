#pragma once
// The argument checks of the device interface (device.hpp), shared by every back end so that
// all of them reject the same input with the same message.

#include <cstddef>
#include <cstdint>
#include <span>

#include "recode/raster/device.hpp"

namespace recode::raster {

// Throws std::invalid_argument unless 1 <= width, height <= kMaxFramebufferSize.
void checkFramebufferSize(int width, int height);

// Throws std::invalid_argument for an index count that is not a multiple of three, an index out
// of range, or a referenced vertex that is not finite, lies beyond kMaxWindowCoordinate or has
// z outside [0, 1]. Checks the whole draw, so a device can validate before changing any pixel.
void checkDraw(std::span<const WindowVertex> vertices, std::span<const std::uint32_t> indices);
// The indices' part of checkDraw alone: a count that is a multiple of three, each below
// vertexCount (a posed draw, whose vertices the source vouches for).
void checkIndices(std::size_t vertexCount, std::span<const std::uint32_t> indices);

// Throw std::invalid_argument ("<what>: unknown compare function 9") for a value outside its
// enumeration: a setter checks before it changes any state (RenderStateDevice calls them).
void checkCompareFunc(CompareFunc func, const char* what);
void checkStencilOps(const StencilOps& ops);
void checkFace(Face face);
void checkCullMode(CullMode mode);

}  // namespace recode::raster
