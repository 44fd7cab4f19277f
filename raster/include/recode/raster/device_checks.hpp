#pragma once
// The argument checks of the device interface (device.hpp), shared by every back end so that
// all of them reject the same input with the same message.

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

}  // namespace recode::raster
