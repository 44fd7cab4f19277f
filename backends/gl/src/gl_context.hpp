#pragma once
// The GL context behind a GlDevice, kept apart from the device so that another way of getting
// a context (EGL on a real GPU, a window system) is a new class here and not a rewrite of the
// device. Private to recode_backend_gl: this header may name GL types, public headers may not.

#include <memory>
#include <string>

namespace recode::backends::detail {

// A context with a default framebuffer of exactly width x height pixels, a 24-bit depth and an
// 8-bit stencil buffer, and GL 4.5 compatibility-profile entry points (client vertex arrays and
// the fixed-function matrix stack, plus glClipControl).
class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread (cheap when it already is).
  void makeCurrent() {
    if (current_ == this)
      return;
    bind();
    current_ = this;
  }

  // Resolves a GL entry point that the library does not export under its own name
  // (glClipControl on OSMesa). Returns nullptr when there is none.
  using Proc = void (*)();
  [[nodiscard]] virtual Proc procAddress(const char* name) = 0;

  // The renderer's own name ("llvmpipe (LLVM 15, 256 bits)"), for reports.
  [[nodiscard]] virtual std::string renderer() = 0;

 protected:
  // Binds this context to the calling thread even if the API believes it is bound already:
  // OSMesa and Mesa's EGL share one dispatch, so another library's context may have taken it
  // over without the API's own "current context" noticing.
  virtual void bind() = 0;
  // For destructors: this context is no longer bound anywhere.
  void forget() {
    if (current_ == this)
      current_ = nullptr;
  }

 private:
  // The context this process last bound on this thread, whatever its kind: the only record that
  // sees every switch, because every context goes through makeCurrent.
  static inline thread_local const GlContext* current_ = nullptr;
};

// An OSMesa (Mesa llvmpipe) context rendering into memory the context owns. Throws
// std::runtime_error when OSMesa cannot create it or gives other depth/stencil sizes.
[[nodiscard]] std::unique_ptr<GlContext> makeOsMesaContext(int width, int height);

// An OSMesa context of OpenGL 4.5 core profile with a 1x1 colour buffer and no depth or
// stencil: for devices that render into their own framebuffer object.
[[nodiscard]] std::unique_ptr<GlContext> makeOsMesaCoreContext();

// A headless EGL context of OpenGL 4.5 core profile without any surface: Mesa's surfaceless
// platform, or the first device of the EGL device platform. Throws std::runtime_error saying
// what is missing. Defined only when the build has EGL (RECODE_HAVE_EGL).
[[nodiscard]] std::unique_ptr<GlContext> makeEglHeadlessContext();

// The same with an OpenGL 4.5 compatibility-profile context (the fixed-function GlDevice, which
// draws into its own framebuffer object there). Defined only with EGL.
[[nodiscard]] std::unique_ptr<GlContext> makeEglCompatibilityContext();

}  // namespace recode::backends::detail
