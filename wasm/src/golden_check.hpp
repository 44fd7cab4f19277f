#pragma once
// A golden vector replayed by the module's CPU device (the WebAssembly build of the
// reference), so that a test can show it gives the native build's bits.

#include <string>

namespace recode::wasm {

// {"depth_pixels", "stencil_pixels", "first_difference"}: the pixels that differ from the
// vector's expected buffers (0 and 0, null: the same bits). Throws raster::FormatError for a
// malformed file.
[[nodiscard]] std::string checkGolden(const std::string& path);

}  // namespace recode::wasm
