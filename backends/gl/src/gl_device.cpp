// GlDevice: the device interface mapped one to one onto OpenGL 4.5 compatibility-profile state.
// How window coordinates reach GL unchanged, and why depth goes through glClipControl, is in
// docs/verification.md (the GL device section). Every GL call goes through function pointers the
// context resolves (gl_functions.hpp), so the device runs on OSMesa, whose library exports them,
// and on EGL, whose library exports none: on EGL it draws into a framebuffer object of its own
// with a DEPTH24_STENCIL8 renderbuffer, as OSMesa's default framebuffer is.

#include "recode/backends/gl_device.hpp"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gl_context.hpp"
#include "gl_enums.hpp"
#include "gl_functions.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"

namespace recode::backends {

namespace {

using raster::CompareFunc;
using raster::PixelRect;

// The entry points the device calls, resolved through its context.
struct GlFunctions {
  detail::GlCoreFunctions core;
  detail::GlLegacyFunctions legacy;
};

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
WindowViewport placeUnclippedViewport(const GlFunctions& gl, int width, int height) {
  GLint maxViewport[2] = {0, 0};
  GLint bounds[2] = {0, 0};
  gl.core.GetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  gl.core.GetIntegerv(GL_VIEWPORT_BOUNDS_RANGE, bounds);
  const Viewport vx = viewportFor(width, maxViewport[0], bounds[0]);
  const Viewport vy = viewportFor(height, maxViewport[1], bounds[0]);
  if (vx.size < width || vy.size < height) {
    throw std::runtime_error("GlDevice: GL_MAX_VIEWPORT_DIMS " + std::to_string(maxViewport[0]) +
                             "x" + std::to_string(maxViewport[1]) + " is smaller than the " +
                             std::to_string(width) + "x" + std::to_string(height) + " framebuffer");
  }
  gl.core.Viewport(vx.origin, vy.origin, vx.size, vy.size);
  return {vx, vy};
}

// Depth: with glClipControl's ZERO_TO_ONE convention window z = z_ndc, so a projection that
// passes z through leaves it unchanged. (GL's default -1..1 convention needs z_ndc = 2z - 1,
// which loses low bits of small z before the rasterizer sees them.)
void passDepthThrough(const GlFunctions& gl) {
  gl.legacy.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl.legacy.DepthRange(0.0, 1.0);
}

// The projection that undoes the viewport transform, so that window coordinates come out as
// they went in. Column-major: x_clip = (x - cx) * 2/P, y_clip = (y - cy) * 2/Q, z_clip = z,
// w = 1.
void loadWindowProjection(const GlFunctions& gl, const WindowViewport& viewport) {
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
  gl.legacy.MatrixMode(detail::kGlProjection);
  gl.legacy.LoadMatrixf(projection);
  gl.legacy.MatrixMode(detail::kGlModelview);
  gl.legacy.LoadIdentity();
}

// The tests are always on; "off" is ALWAYS, as docs/rasterization.md section 6 says. No
// colour is written, and nothing else in the fragment pipeline may change a fragment.
void setFixedFragmentState(const GlFunctions& gl, int width, int height) {
  gl.core.Enable(GL_DEPTH_TEST);
  gl.core.Enable(GL_STENCIL_TEST);
  gl.core.Enable(GL_SCISSOR_TEST);
  gl.core.Disable(GL_CULL_FACE);
  gl.core.Disable(GL_DEPTH_CLAMP);
  gl.core.Disable(GL_POLYGON_OFFSET_FILL);
  gl.core.Disable(GL_MULTISAMPLE);
  gl.core.Disable(GL_DITHER);
  gl.legacy.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gl.legacy.FrontFace(GL_CCW);
  gl.legacy.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.core.DepthFunc(GL_LESS);
  gl.core.DepthMask(GL_TRUE);
  gl.core.StencilFunc(GL_ALWAYS, 0, 0xFF);
  gl.legacy.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gl.core.StencilMask(0xFF);
  gl.core.Scissor(0, 0, width, height);
  gl.core.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.legacy.EnableClientState(detail::kGlVertexArray);
}

// Start as CpuDevice starts: depth 1.0, stencil 0 (OSMesa's buffers start undefined).
void clearAsCpuDeviceStarts(const GlFunctions& gl) {
  gl.core.ClearDepth(1.0);
  gl.core.ClearStencil(0);
  gl.core.Clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

}  // namespace

struct GlDevice::Impl {
  std::unique_ptr<detail::GlContext> context;
  GlPlatform platform = GlPlatform::OsMesa;
  GlFunctions gl;
  GLuint framebuffer = 0;  // on EGL: the device's own; on OSMesa 0, the context's
  GLuint depthStencil = 0;
  std::vector<GLfloat> vertexScratch;  // snapped x, y, z per vertex, reused between draws
  // Each read-back waits for every command before it (glReadPixels into client memory).
  raster::TransferCounters transfers;

  // Makes the context current; every public entry point starts here.
  void use() { context->makeCurrent(); }

  // A GL error here is a bug in this file (every input was validated), so it is reported
  // loudly rather than ignored.
  void check(const char* what) const { detail::throwOnGlError(gl.core, "GlDevice", what); }

  // The context of the platform asked for: OSMesa's with its own width x height framebuffer,
  // or EGL's (compatibility profile) with none; auto takes OSMesa when built, else EGL.
  void makeContext(GlPlatform requested, int width, int height) {
#ifdef RECODE_HAVE_OSMESA
    if (requested != GlPlatform::Egl) {
      context = detail::makeOsMesaContext(width, height);
      platform = GlPlatform::OsMesa;
      return;
    }
#else
    if (requested == GlPlatform::OsMesa)
      throw std::runtime_error(
          "GlDevice: this build has no OSMesa (Debian: apt-get install libosmesa6-dev, then "
          "reconfigure)");
#endif
#ifdef RECODE_HAVE_EGL
    context = detail::makeEglCompatibilityContext();
    platform = GlPlatform::Egl;
#else
    (void)width;
    (void)height;
    throw std::runtime_error(
        "GlDevice: this build has no EGL (Debian: apt-get install libegl-dev, then "
        "reconfigure)");
#endif
  }

  // On EGL: a framebuffer object with a DEPTH24_STENCIL8 renderbuffer and no colour, the
  // depth and stencil OSMesa's default framebuffer has.
  void createFramebuffer(int width, int height) {
    const detail::DepthStencilFramebuffer made = detail::createDepthStencilFramebuffer(
        gl.core, GL_DEPTH24_STENCIL8, "DEPTH24_STENCIL8", width, height, "GlDevice");
    framebuffer = made.framebuffer;
    depthStencil = made.renderbuffer;
  }

  ~Impl() {
    if (!context || framebuffer == 0)
      return;
    try {
      use();
      gl.core.DeleteFramebuffers(1, &framebuffer);
      gl.core.DeleteRenderbuffers(1, &depthStencil);
    } catch (...) {  // NOLINT(bugprone-empty-catch): the objects die with the context
    }
  }
};

GlDevice::GlDevice(int width, int height, GlPlatform platform)
    : RenderStateDevice(width, height), width_(width), height_(height) {
  raster::checkFramebufferSize(width, height);
  impl_ = std::make_unique<Impl>();
  Impl& d = *impl_;
  d.makeContext(platform, width, height);
  d.use();
  d.gl = {detail::loadGlCoreFunctions(*d.context), detail::loadGlLegacyFunctions(*d.context)};
  if (d.platform == GlPlatform::Egl)
    d.createFramebuffer(width, height);
  // Each step below sets GL state the device relies on from here on; none is changed again
  // except through the device interface.
  const WindowViewport viewport = placeUnclippedViewport(d.gl, width, height);
  passDepthThrough(d.gl);
  loadWindowProjection(d.gl, viewport);
  setFixedFragmentState(d.gl, width, height);
  clearAsCpuDeviceStarts(d.gl);
  d.check("GlDevice setup");
}

GlPlatform GlDevice::platform() const {
  return impl_->platform;
}

GlDevice::~GlDevice() = default;

std::string GlDevice::renderer() const {
  return impl_->context->renderer();
}

// RenderStateDevice's setters have checked and stored the change; it is set on GL here.
void GlDevice::stateChanged(StateChange change, raster::Face face) {
  impl_->use();
  const GlFunctions& gl = impl_->gl;
  switch (change) {
    case StateChange::Scissor: {  // clamped to the framebuffer; empty is a zero-sized scissor
      const PixelRect& r = state_.scissor;
      gl.core.Scissor(r.x0, r.y0, r.width(), r.height());
      return;
    }
    case StateChange::DepthFunc:
      gl.core.DepthFunc(detail::glCompareEnum(state_.depthFunc));
      return;
    case StateChange::DepthWriteMask:
      gl.core.DepthMask(state_.depthWrite ? GL_TRUE : GL_FALSE);
      return;
    case StateChange::StencilFunc:  // one func for both faces, as in the device interface
      gl.core.StencilFunc(detail::glCompareEnum(state_.stencilFunc), state_.stencilRef,
                          state_.stencilValueMask);
      return;
    case StateChange::StencilOps: {
      const raster::StencilOps& ops = face == raster::Face::Back ? state_.backOps : state_.frontOps;
      gl.core.StencilOpSeparate(detail::glFaceEnum(face), detail::glStencilOpEnum(ops.stencilFail),
                                detail::glStencilOpEnum(ops.depthFail),
                                detail::glStencilOpEnum(ops.depthPass));
      return;
    }
    case StateChange::StencilWriteMask:
      gl.core.StencilMask(state_.stencilWriteMask);
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
  const GlFunctions& gl = impl_->gl;
  gl.core.ClearDepth(depth);  // GL clamps to [0, 1]; the depth write mask applies to the clear
  gl.core.Clear(GL_DEPTH_BUFFER_BIT);
}

void GlDevice::clearStencil(std::uint8_t value) {
  impl_->use();
  const GlFunctions& gl = impl_->gl;
  gl.core.ClearStencil(value);  // the stencil write mask applies to the clear
  gl.core.Clear(GL_STENCIL_BUFFER_BIT);
}

void GlDevice::applyCullMode(raster::CullMode mode) {
  const GlFunctions& gl = impl_->gl;
  switch (mode) {
    case raster::CullMode::None:
      gl.core.Disable(GL_CULL_FACE);
      return;
    case raster::CullMode::Front:
      gl.core.Enable(GL_CULL_FACE);
      gl.legacy.CullFace(GL_FRONT);
      return;
    case raster::CullMode::Back:
      gl.core.Enable(GL_CULL_FACE);
      gl.legacy.CullFace(GL_BACK);
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
  const GlFunctions& gl = impl_->gl;
  gl.legacy.VertexPointer(3, GL_FLOAT, 0, xyz.data());
  // glDrawElements counts in GLsizei; split a (huge) draw into whole triangles that fit.
  constexpr std::size_t kChunk = static_cast<std::size_t>(INT_MAX / 3) * 3;
  for (std::size_t first = 0; first < indices.size(); first += kChunk) {
    const std::size_t count = std::min(kChunk, indices.size() - first);
    gl.legacy.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
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
  const GlFunctions& gl = impl_->gl;
  // glReadPixels returns rows from the bottom (y = r.y0) up, the interface's order; neither
  // the scissor nor the write masks affect it.
  const auto waiting = std::chrono::steady_clock::now();  // glReadPixels waits for the draws
  gl.core.ReadPixels(r.x0, r.y0, r.width(), r.height(), GL_STENCIL_INDEX, GL_UNSIGNED_BYTE,
                     out.data());
  impl_->check("readStencil");
  impl_->transfers.waitUs +=
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - waiting).count();
  ++impl_->transfers.submissions;
  impl_->transfers.readbackBytes += static_cast<long long>(out.size());
  return out;
}

std::vector<std::uint32_t> GlDevice::readDepth(const PixelRect& rect) const {
  const PixelRect r = rect.intersect({0, 0, width_, height_});
  if (r.empty())
    return {};
  std::vector<std::uint32_t> out(static_cast<std::size_t>(r.area()));
  impl_->use();
  const GlFunctions& gl = impl_->gl;
  // GL_UNSIGNED_INT_24_8 hands back the stored 24-bit depth unconverted in the top 24 bits
  // (GL_DEPTH_COMPONENT as GL_UNSIGNED_INT would rescale it to 32 bits and round).
  const auto waiting = std::chrono::steady_clock::now();  // glReadPixels waits for the draws
  gl.core.ReadPixels(r.x0, r.y0, r.width(), r.height(), GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                     out.data());
  impl_->check("readDepth");
  impl_->transfers.waitUs +=
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - waiting).count();
  ++impl_->transfers.submissions;
  impl_->transfers.readbackBytes += static_cast<long long>(4 * out.size());
  for (std::uint32_t& word : out)
    word >>= 8;
  return out;
}

raster::TransferCounters GlDevice::transfers() const {
  return impl_->transfers;
}

}  // namespace recode::backends
