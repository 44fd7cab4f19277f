# RECODE_WITH_WASM: the WebAssembly module of the reference (wasm/, docs/wasm.md), built with
# emscripten as a project of its own inside this build (build/wasm-module, the same sources
# configured by emcmake), then embedded into `recode` for the interactive page and run by the
# `wasm/` tests under Node. ON when emscripten is installed (scripts/setup.sh installs it);
# scripts/build-wasm.sh builds the module alone.
find_program(RECODE_EMCMAKE emcmake)
if(RECODE_EMCMAKE)
  option(RECODE_WITH_WASM "Build the WebAssembly module (emscripten)" ON)
else()
  option(RECODE_WITH_WASM "Build the WebAssembly module (emscripten)" OFF)
endif()
if(RECODE_WITH_WASM AND NOT RECODE_EMCMAKE)
  message(FATAL_ERROR "RECODE_WITH_WASM is ON but emcmake was not found: apt-get install "
                      "emscripten (scripts/setup.sh)")
endif()
if(RECODE_WITH_WASM)
  include(ExternalProject)
  set(RECODE_WASM_MODULE_JS ${CMAKE_BINARY_DIR}/wasm-module/wasm/recode-wasm.js)
  # Debian's emscripten runs its optimizer under Node with acorn from Debian's Node modules,
  # found only through NODE_PATH.
  set(node_path ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
  ExternalProject_Add(recode_wasm_module
    SOURCE_DIR ${PROJECT_SOURCE_DIR}
    BINARY_DIR ${CMAKE_BINARY_DIR}/wasm-module
    CONFIGURE_COMMAND ${node_path} ${RECODE_EMCMAKE} ${CMAKE_COMMAND} -S <SOURCE_DIR>
                      -B <BINARY_DIR> -G Ninja -DCMAKE_BUILD_TYPE=Release
                      -DRECODE_WERROR=${RECODE_WERROR}
    BUILD_COMMAND ${node_path} ${CMAKE_COMMAND} --build <BINARY_DIR> --target recode_wasm
    INSTALL_COMMAND ""
    # Its own ninja decides what is out of date; this only asks it every time.
    BUILD_ALWAYS ON
    BUILD_BYPRODUCTS ${RECODE_WASM_MODULE_JS}
    USES_TERMINAL_BUILD ON)
endif()
