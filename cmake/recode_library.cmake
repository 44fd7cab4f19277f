# recode_add_library(NAME sources...): the one way a RECODE library is declared. Makes the
# static library recode_NAME, its alias recode::NAME, the public include folder include/ beside
# the calling CMakeLists.txt (include/ again once installed), exports it as recode::NAME
# (cmake/install.cmake) and builds it as C++20 with the project's warnings, which stay out of
# its exported interface. The caller adds what it links.
#
# Position-independent code, so that the static libraries can be linked into a shared object:
# the Python module (python/) or a user's plugin. -fno-semantic-interposition keeps GCC
# inlining the libraries' own global functions as it does without -fPIC (no one interposes a
# symbol of a static library); neither flag changes floating-point code.
function(recode_add_library name)
  set(target recode_${name})
  add_library(${target} STATIC ${ARGN})
  add_library(recode::${name} ALIAS ${target})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                              $<INSTALL_INTERFACE:include>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_compile_features(${target} PUBLIC cxx_std_20)
  if(NOT EMSCRIPTEN)  # a WebAssembly module is one program: nothing to share or interpose
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif()
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:recode_warnings>)
endfunction()
