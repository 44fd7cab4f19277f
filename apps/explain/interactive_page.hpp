#pragma once
// `recode explain --interactive --out DIR`: DIR/index.html, the interactive page. One file that
// opens from file:// with nothing beside it: the reference compiled to WebAssembly (wasm/,
// embedded at build time), the page's script (page/interactive.js) and the ray inspector.

#include <filesystem>

namespace recode::app::explain {

// Writes DIR/index.html into the existing directory `dir`. Throws std::runtime_error naming
// what to install when this build has no WebAssembly module, or the file on a write error.
void writeInteractivePage(const std::filesystem::path& dir);

}  // namespace recode::app::explain
