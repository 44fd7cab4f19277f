# The Embree per-pixel interval oracle. Embree stays in these translation units: the public
# header (embree_oracle.hpp) names no Embree type.
if(NOT embree_FOUND)
  message(FATAL_ERROR "RECODE_WITH_EMBREE is ON but CMake found no embree 3 package "
                      "(Debian: apt-get install libembree-dev)")
endif()
target_sources(recode_verify PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/embree_window_block.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/embree_ray_caster.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/embree_oracle.cpp)
target_link_libraries(recode_verify PRIVATE embree)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_EMBREE=1)
