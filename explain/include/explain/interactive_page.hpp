#pragma once
// `recode explain --interactive --out DIR`: DIR/index.html, the interactive page. One file that
// opens from file:// with nothing beside it: the reference compiled to WebAssembly (wasm/, handed
// in by the program that embeds it), the page's scripts (page/) and the ray inspector.

#include <filesystem>
#include <string_view>

namespace recode::explain {

// Writes DIR/index.html into the existing directory `dir`, with `wasmModuleJs` (wasm/'s
// recode-wasm.js) inlined. Throws std::runtime_error naming the file on a write error, or a
// script that cannot be inlined.
void writeInteractivePage(const std::filesystem::path& dir, std::string_view wasmModuleJs);

}  // namespace recode::explain
