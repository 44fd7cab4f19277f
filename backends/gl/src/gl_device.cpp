// GlDevice: the device interface mapped one to one onto OpenGL 4.5 compatibility-profile state.
// How window coordinates reach GL unchanged, and why depth goes through glClipControl, is in
// docs/verification.md (the GL device section).

#include "recode/backends/gl_device.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "gl_context.hpp"
#include "gl_enums.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"

namespace recode::backends {

namespace {

using raster::CompareFunc;
using raster::PixelRect;

// One axis of the viewport: the largest power of two GL allows, centred on the framebuffer
// (the origin kept within GL_VIEWPORT_BOUNDS_RANGE).
struct Viewport {
  GLint origin = 0;
  GLint size = 1;
  [[nodiscard]] GLint centre() const { return origin + size / 2; }
};

Viewport viewportFor(int framebuffer, GLint maxSize, GLint lowestOrigin) {
  Viewport v;
  while (v.size * 2 <= maxSize)
    v.size *= 2;
  v.origin = std::max<GLint>(-(v.size - framebuffer) / 2, lowestOrigin);
  return v;
}

// Both axes: the projection must undo exactly the viewport that was set.
struct WindowViewport {
  Viewport x, y;
};

// Window coordinates must reach the rasterizer unchanged, and must not be clipped: llvmpipe
// clips x and y at the viewport's edges (no guard band), and a clipped triangle gets new,
// off-grid vertices. So the viewport is as large as GL allows, P x Q with P, Q powers of
// two, and placed around the framebuffer with a band of (P - W) / 2 pixels on either side
// (about 8,000 for small frames). Vertices inside it are drawn exactly as given: with c the
// viewport's centre, x_ndc = (x - c) * 2/P and x_w = x_ndc * P/2 + c are exact in float for
// every x on the 1/256 grid within +-32768 (x - c has at most 24 significant bits).
WindowViewport placeUnclippedViewport(int width, int height) {
  GLint maxViewport[2] = {0, 0};
  GLint bounds[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  glGetIntegerv(GL_VIEWPORT_BOUNDS_RANGE, bounds);
  const Viewport vx = viewportFor(width, maxViewport[0], bounds[0]);
  const Viewport vy = viewportFor(height, maxViewport[1], bounds[0]);
  if (vx.size < width || vy.size < height) {
    throw std::runtime_error("GlDevice: GL_MAX_VIEWPORT_DIMS " + std::to_string(maxViewport[0]) +
                             "x" + std::to_string(maxViewport[1]) + " is smaller than the " +
                             std::to_string(width) + "x" + std::to_string(height) + " framebuffer");
  }
  glViewport(vx.origin, vy.origin, vx.size, vy.size);
  return {vx, vy};
}

// Depth: with glClipControl's ZERO_TO_ONE convention window z = z_ndc, so a projection that
// passes z through leaves it unchanged. (GL's default -1..1 convention needs z_ndc = 2z - 1,
// which loses low bits of small z before the rasterizer sees them.)
void passDepthThrough(detail::GlContext& context) {
  const auto clipControl =
      reinterpret_cast<PFNGLCLIPCONTROLPROC>(context.procAddress("glClipControl"));
  if (clipControl == nullptr)
    throw std::runtime_error("GlDevice: the GL implementation has no glClipControl (GL 4.5)");
  clipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthRange(0.0, 1.0);
}

// The projection that undoes the viewport transform, so that window coordinates come out as
// they went in. Column-major: x_clip = (x - cx) * 2/P, y_clip = (y - cy) * 2/Q, z_clip = z,
// w = 1.
void loadWindowProjection(const WindowViewport& viewport) {
  const Viewport& vx = viewport.x;
  const Viewport& vy = viewport.y;
  const GLfloat sx = 2.0f / static_cast<GLfloat>(vx.size);
  const GLfloat sy = 2.0f / static_cast<GLfloat>(vy.size);
  const GLfloat projection[16] = {sx,
                                  0.0f,
                                  0.0f,
                                  0.0f,  //
                                  0.0f,
                                  sy,
                                  0.0f,
                                  0.0f,  //
                                  0.0f,
                                  0.0f,
                                  1.0f,
                                  0.0f,  //
                                  -static_cast<GLfloat>(vx.centre()) * sx,
                                  -static_cast<GLfloat>(vy.centre()) * sy,
                                  0.0f,
                                  1.0f};
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(projection);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// The tests are always on; "off" is ALWAYS, as docs/rasterization.md section 6 says. No
// colour is written, and nothing else in the fragment pipeline may change a fragment.
void setFixedFragmentState(int width, int height) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_DITHER);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glFrontFace(GL_CCW);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xFF);
  glScissor(0, 0, width, height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glEnableClientState(GL_VERTEX_ARRAY);
}

// Start as CpuDevice starts: depth 1.0, stencil 0 (OSMesa's buffers start undefined).
void clearAsCpuDeviceStarts() {
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

}  // namespace

struct GlDevice::Impl {
  std::unique_ptr<detail::GlContext> context;
  std::vector<GLfloat> vertexScratch;  // snapped x, y, z per vertex, reused between draws

  // Makes the context current; every public entry point starts here.
  void use() { context->makeCurrent(); }

  // A GL error here is a bug in this file (every input was validated), so it is reported
  // loudly rather than ignored.
  static void check(const char* what) {
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
      char code[16];
      std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(error));
      throw std::runtime_error(std::string("GlDevice: GL error ") + code + " in " + what);
    }
  }
};

GlDevice::GlDevice(int width, int height)
    : RenderStateDevice(width, height), width_(width), height_(height) {
  raster::checkFramebufferSize(width, height);
  impl_ = std::make_unique<Impl>();
  impl_->context = detail::makeOsMesaContext(width, height);
  impl_->use();
  // Each step below sets GL state the device relies on from here on; none is changed again
  // except through the device interface.
  const WindowViewport viewport = placeUnclippedViewport(width, height);
  passDepthThrough(*impl_->context);
  loadWindowProjection(viewport);
  setFixedFragmentState(width, height);
  clearAsCpuDeviceStarts();
  impl_->check("GlDevice setup");
}

GlDevice::~GlDevice() = default;

std::string GlDevice::renderer() const {
  return impl_->context->renderer();
}

// RenderStateDevice's setters have checked and stored the change; it is set on GL here.
void GlDevice::stateChanged(StateChange change, raster::Face face) {
  impl_->use();
  switch (change) {
    case StateChange::Scissor: {  // clamped to the framebuffer; empty is a zero-sized scissor
      const PixelRect& r = state_.scissor;
      glScissor(r.x0, r.y0, r.width(), r.height());
      return;
    }
    case StateChange::DepthFunc:
      glDepthFunc(detail::glCompareEnum(state_.depthFunc));
      return;
    case StateChange::DepthWriteMask:
      glDepthMask(state_.depthWrite ? GL_TRUE : GL_FALSE);
      return;
    case StateChange::StencilFunc:  // one func for both faces, as in the device interface
      glStencilFunc(detail::glCompareEnum(state_.stencilFunc), state_.stencilRef,
                    state_.stencilValueMask);
      return;
    case StateChange::StencilOps: {
      const raster::StencilOps& ops = face == raster::Face::Back ? state_.backOps : state_.frontOps;
      glStencilOpSeparate(detail::glFaceEnum(face), detail::glStencilOpEnum(ops.stencilFail),
                          detail::glStencilOpEnum(ops.depthFail),
                          detail::glStencilOpEnum(ops.depthPass));
      return;
    }
    case StateChange::StencilWriteMask:
      glStencilMask(state_.stencilWriteMask);
      return;
    case StateChange::CullMode:
      applyCullMode(state_.cull);
      return;
  }
}

void GlDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  impl_->use();
  glClearDepth(depth);  // GL clamps to [0, 1]; the depth write mask applies to the clear
  glClear(GL_DEPTH_BUFFER_BIT);
}

void GlDevice::clearStencil(std::uint8_t value) {
  impl_->use();
  glClearStencil(value);  // the stencil write mask applies to the clear
  glClear(GL_STENCIL_BUFFER_BIT);
}

void GlDevice::applyCullMode(raster::CullMode mode) {
  switch (mode) {
    case raster::CullMode::None:
      glDisable(GL_CULL_FACE);
      return;
    case raster::CullMode::Front:
      glEnable(GL_CULL_FACE);
      glCullFace(GL_FRONT);
      return;
    case raster::CullMode::Back:
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
      return;
  }
}

void GlDevice::drawTriangles(std::span<const raster::WindowVertex> vertices,
                             std::span<const std::uint32_t> indices) {
  raster::checkDraw(vertices, indices);
  if (indices.empty())
    return;
  std::vector<GLfloat>& xyz = impl_->vertexScratch;
  xyz.resize(vertices.size() * 3);
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    xyz[3 * k] = raster::snapToSubpixel(vertices[k].x);
    xyz[3 * k + 1] = raster::snapToSubpixel(vertices[k].y);
    xyz[3 * k + 2] = vertices[k].z;
  }
  impl_->use();
  glVertexPointer(3, GL_FLOAT, 0, xyz.data());
  // glDrawElements counts in GLsizei; split a (huge) draw into whole triangles that fit.
  constexpr std::size_t kChunk = static_cast<std::size_t>(INT_MAX / 3) * 3;
  for (std::size_t first = 0; first < indices.size(); first += kChunk) {
    const std::size_t count = std::min(kChunk, indices.size() - first);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                   indices.data() + first);
  }
  impl_->check("drawTriangles");
}

std::vector<std::uint8_t> GlDevice::readStencil(const PixelRect& rect) const {
  const PixelRect r = rect.intersect({0, 0, width_, height_});
  if (r.empty())
    return {};
  std::vector<std::uint8_t> out(static_cast<std::size_t>(r.area()));
  impl_->use();
  // glReadPixels returns rows from the bottom (y = r.y0) up, the interface's order; neither
  // the scissor nor the write masks affect it.
  glReadPixels(r.x0, r.y0, r.width(), r.height(), GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out.data());
  impl_->check("readStencil");
  return out;
}

std::vector<std::uint32_t> GlDevice::readDepth(const PixelRect& rect) const {
  const PixelRect r = rect.intersect({0, 0, width_, height_});
  if (r.empty())
    return {};
  std::vector<std::uint32_t> out(static_cast<std::size_t>(r.area()));
  impl_->use();
  // GL_UNSIGNED_INT_24_8 hands back the stored 24-bit depth unconverted in the top 24 bits
  // (GL_DEPTH_COMPONENT as GL_UNSIGNED_INT would rescale it to 32 bits and round).
  glReadPixels(r.x0, r.y0, r.width(), r.height(), GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
               out.data());
  impl_->check("readDepth");
  for (std::uint32_t& word : out)
    word >>= 8;
  return out;
}

}  // namespace recode::backends
