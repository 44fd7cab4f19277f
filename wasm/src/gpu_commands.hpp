#pragma once
// A golden vector as a GPU back end without 64-bit arithmetic replays it (the WebGPU page,
// backends/webgpu/): the CPU half of the exact devices done here, in the module, so that the
// page only draws.

#include <string>

namespace recode::wasm {

// The golden vector (recode-golden-1) or command stream (recode-commands-1) at `path` as
// {"width", "height", "commands", "depth", "stencil"}. Each command, in stream order, is one of
// {"draw": state, "proxies": [18 words per record, as backends::ProxyTriangle lays them out]},
// {"clear_depth": state, "q": the quantised value} (only when the depth mask lets it write) or
// {"clear_stencil": state, "value": v}, where a state is the render state the command sees:
// scissor, depth func and mask, stencil func, ref, masks, front and back ops. Culling is already
// applied to the proxies. "depth" (24-bit q) and "stencil" are the expected buffers, bottom row
// first: a golden vector's own, or for a command stream the CPU device's after replaying it. Throws
// raster::FormatError for a malformed file, std::invalid_argument for an invalid draw.
[[nodiscard]] std::string gpuCommands(const std::string& path);

}  // namespace recode::wasm
