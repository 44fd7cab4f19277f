#pragma once
// The WebAssembly module (wasm/'s recode-wasm.js, the module embedded) that `recode explain
// --interactive` puts into its page, embedded into the program at build time when this build
// has one (RECODE_WITH_WASM, cmake/wasm_module.cmake).

namespace recode::app {

#if RECODE_HAVE_WASM_MODULE
extern const char* const kRecodeWasmJs;
#endif

}  // namespace recode::app
