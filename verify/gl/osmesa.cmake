# The GL devices on OSMesa (Mesa llvmpipe) and the CPU/GL parity comparison. OSMesa stays in
# these translation units: the public headers name no GL type. libOSMesa exports the gl* entry
# points itself; linking libGL / OpenGL::GL as well would make every GL call do nothing (GLVND's
# libGL dispatches to no context), so it is deliberately absent. (libEGL, added by egl.cmake,
# exports no gl* symbol and does not interfere.)
if(NOT OSMESA_FOUND)
  message(FATAL_ERROR "RECODE_WITH_OSMESA is ON but pkg-config found no osmesa "
                      "(Debian: apt-get install libosmesa6-dev)")
endif()
target_sources(recode_verify PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/osmesa_context.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/gl_device.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/gl_parity.cpp)
target_link_libraries(recode_verify PRIVATE PkgConfig::OSMESA)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_OSMESA=1)
