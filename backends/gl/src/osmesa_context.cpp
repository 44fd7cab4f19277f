// OSMesa (Mesa's off-screen GL, llvmpipe) as a GlContext: the context renders into a colour
// buffer in memory that this object owns; depth and stencil live inside Mesa.

#include <GL/osmesa.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl_context.hpp"

namespace recode::backends::detail {

namespace {

class OsMesaContext final : public GlContext {
 public:
  // Takes ownership of context, which renders into a width x height RGBA buffer owned here.
  OsMesaContext(OSMesaContext context, int width, int height)
      : width_(width), height_(height), context_(context) {
    colour_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u, 0);
  }

  ~OsMesaContext() override { release(); }

  void bind() override {
    if (!OSMesaMakeCurrent(context_, colour_.data(), GL_UNSIGNED_BYTE, width_, height_))
      throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
  }

  Proc procAddress(const char* name) override { return OSMesaGetProcAddress(name); }

  std::string renderer() override {
    makeCurrent();
    const auto* name = glGetString(GL_RENDERER);
    return name != nullptr ? std::string(reinterpret_cast<const char*>(name)) : std::string();
  }

 private:
  void release() noexcept {
    if (context_ == nullptr)
      return;
    forget();
    if (OSMesaGetCurrentContext() == context_)
      OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
    context_ = nullptr;
  }

  int width_;
  int height_;
  OSMesaContext context_ = nullptr;
  std::vector<std::uint8_t> colour_;
};

}  // namespace

std::unique_ptr<GlContext> makeOsMesaContext(int width, int height) {
  // RGBA colour (OSMesa needs some colour buffer even though nothing is drawn into it), a
  // 24-bit depth and an 8-bit stencil buffer, which Mesa stores as Z24_UNORM_S8_UINT.
  OSMesaContext handle = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (handle == nullptr)
    throw std::runtime_error("OSMesa: OSMesaCreateContextExt(RGBA, depth 24, stencil 8) failed");
  auto context = std::make_unique<OsMesaContext>(handle, width, height);
  context->makeCurrent();
  GLint maxWidth = 0, maxHeight = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxWidth);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxHeight);
  if (width > maxWidth || height > maxHeight) {
    throw std::runtime_error("OSMesa: framebuffer " + std::to_string(width) + "x" +
                             std::to_string(height) + " exceeds its maximum " +
                             std::to_string(maxWidth) + "x" + std::to_string(maxHeight));
  }
  GLint depthBits = 0, stencilBits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &depthBits);
  glGetIntegerv(GL_STENCIL_BITS, &stencilBits);
  if (depthBits != 24 || stencilBits != 8) {
    // The classic failure: libGL (glvnd) linked ahead of libOSMesa answers every gl* call
    // with nothing, and the bits read back as garbage.
    throw std::runtime_error("OSMesa: context has " + std::to_string(depthBits) + " depth and " +
                             std::to_string(stencilBits) +
                             " stencil bits, expected 24 and 8 (is libGL linked too?)");
  }
  return context;
}

std::unique_ptr<GlContext> makeOsMesaCoreContext() {
  // The exact device renders into its own framebuffer object, so the context's buffers are a
  // single RGBA pixel and no depth or stencil.
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            4,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            5,
                            0};
  OSMesaContext handle = OSMesaCreateContextAttribs(attributes, nullptr);
  if (handle == nullptr)
    throw std::runtime_error("OSMesa: no OpenGL 4.5 core-profile context (Mesa is too old?)");
  auto context = std::make_unique<OsMesaContext>(handle, 1, 1);
  context->makeCurrent();
  return context;
}

}  // namespace recode::backends::detail
