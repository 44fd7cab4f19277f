# A headless EGL context (Mesa's surfaceless platform, or an EGL device on GPU drivers) for the
# exact GL device, so that it runs unchanged on a real GPU. Only the context comes from libEGL:
# the device resolves every GL function through eglGetProcAddress.
if(NOT EGL_FOUND)
  message(FATAL_ERROR "RECODE_WITH_EGL is ON but pkg-config found no egl "
                      "(Debian: apt-get install libegl-dev libegl-mesa0)")
endif()
target_sources(recode_verify PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/egl_context.cpp)
target_link_libraries(recode_verify PRIVATE PkgConfig::EGL)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_EGL=1)
