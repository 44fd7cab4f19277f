// A headless EGL context for the GL devices: Mesa's surfaceless platform here (llvmpipe without
// any window system), or the first EGL device on drivers that offer the device platform instead
// (NVIDIA). The context has no surface at all; a device renders into its own framebuffer object.
// OpenGL 4.5, core profile for the exact device, compatibility profile for the fixed-function
// one.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "gl_context.hpp"

namespace recode::backends::detail {

namespace {

std::string eglErrorName(EGLint error) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(error));
  return hex;
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr)
    return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name)) {
    const bool startsWord = p == list || p[-1] == ' ';
    const bool endsWord = p[length] == '\0' || p[length] == ' ';
    if (startsWord && endsWord)
      return true;
  }
  return false;
}

template <typename F>
F eglFunction(const char* name) {
  auto f = reinterpret_cast<F>(eglGetProcAddress(name));
  if (f == nullptr)
    throw std::runtime_error(std::string("EGL: the library provides no ") + name);
  return f;
}

// The display: the surfaceless platform when the client library offers it, else the first
// device of the device platform.
EGLDisplay headlessDisplay() {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExtensions, "EGL_EXT_platform_base"))
    throw std::runtime_error(
        "EGL: no EGL_EXT_platform_base (is an EGL driver installed? "
        "Debian: apt-get install libegl-mesa0)");
  const auto getPlatformDisplay =
      eglFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY)
      return display;
  }
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
    const auto queryDevices = eglFunction<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    EGLDeviceEXT device = nullptr;
    EGLint count = 0;
    if (queryDevices(1, &device, &count) == EGL_TRUE && count > 0) {
      EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      if (display != EGL_NO_DISPLAY)
        return display;
    }
  }
  throw std::runtime_error(
      "EGL: neither the surfaceless platform "
      "(EGL_MESA_platform_surfaceless) nor an EGL device is available");
}

class EglContext final : public GlContext {
 public:
  explicit EglContext(bool compatibility) : compatibility_(compatibility) {
    display_ = headlessDisplay();
    EGLint major = 0, minor = 0;
    if (eglInitialize(display_, &major, &minor) != EGL_TRUE)
      throw std::runtime_error("EGL: eglInitialize failed (" + eglErrorName(eglGetError()) + ")");
    createContext();
  }

  // The display stays initialized: every context of the process lives on the same headless
  // display, and eglTerminate would end the others' too (the fixed-function devices each have a
  // context of their own, made and destroyed while others draw).
  ~EglContext() override {
    forget();
    if (eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }

  void bind() override {
    // GLVND skips a make-current of the context it thinks is current, so release it first.
    if (eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
      throw std::runtime_error("EGL: eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
  }

  Proc procAddress(const char* name) override { return eglGetProcAddress(name); }

  std::string renderer() override {
    makeCurrent();
    using GetString = const unsigned char* (*)(unsigned);
    const auto getString = reinterpret_cast<GetString>(eglGetProcAddress("glGetString"));
    const unsigned char* name =
        getString != nullptr ? getString(0x1F01 /* GL_RENDERER */) : nullptr;
    return name != nullptr ? std::string(reinterpret_cast<const char*>(name)) : std::string();
  }

 private:
  void createContext() {
    const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context") ||
        !hasExtension(extensions, "EGL_KHR_no_config_context")) {
      throw std::runtime_error(
          "EGL: the display lacks EGL_KHR_surfaceless_context or "
          "EGL_KHR_no_config_context");
    }
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE)
      throw std::runtime_error("EGL: the driver offers no desktop OpenGL");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 compatibility_ ? EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
                                                : EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) {
      throw std::runtime_error(std::string("EGL: no OpenGL 4.5 ") +
                               (compatibility_ ? "compatibility" : "core") + "-profile context (" +
                               eglErrorName(eglGetError()) + ")");
    }
    makeCurrent();
  }

  bool compatibility_ = false;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> makeEglHeadlessContext() {
  return std::make_unique<EglContext>(false);
}

std::unique_ptr<GlContext> makeEglCompatibilityContext() {
  return std::make_unique<EglContext>(true);
}

}  // namespace recode::backends::detail
