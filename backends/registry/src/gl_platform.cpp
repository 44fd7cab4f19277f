#include "recode/backends/gl_platform.hpp"

#include <stdexcept>

namespace recode::backends {

bool glPlatformBuilt(GlPlatform platform) {
  switch (platform) {
    case GlPlatform::OsMesa:
#ifdef RECODE_HAVE_OSMESA
      return true;
#else
      return false;
#endif
    case GlPlatform::Egl:
#ifdef RECODE_HAVE_EGL
      return true;
#else
      return false;
#endif
    case GlPlatform::Auto:
      return glPlatformBuilt(GlPlatform::OsMesa) || glPlatformBuilt(GlPlatform::Egl);
  }
  return false;
}

#ifndef RECODE_HAVE_GL_EXACT
// With the exact GL device, resolveGlPlatform is its own (gl_exact_device.cpp).
GlPlatform resolveGlPlatform(GlPlatform) {
  throw std::runtime_error(
      "this build has no exact GL device (Debian: apt-get install libosmesa6-dev or libegl-dev, "
      "then reconfigure)");
}
#endif

}  // namespace recode::backends
