# recode_add_library(NAME sources...): the one way a RECODE library is declared. Makes the
# static library recode_NAME, its alias recode::NAME, the public include folder include/ beside
# the calling CMakeLists.txt (include/ again once installed), exports it as recode::NAME
# (cmake/install.cmake) and builds it as C++20 with the project's warnings, which stay out of
# its exported interface. The caller adds what it links.
function(recode_add_library name)
  set(target recode_${name})
  add_library(${target} STATIC ${ARGN})
  add_library(recode::${name} ALIAS ${target})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                              $<INSTALL_INTERFACE:include>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:recode_warnings>)
endfunction()
