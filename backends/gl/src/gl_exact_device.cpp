// GlExactDevice: the contract on OpenGL 4.5 core. The CPU validates, snaps and sets up each
// triangle (exact_proxy.cpp); the GPU draws a proxy rectangle per triangle and its shaders
// (shaders/exact_*.glsl) decide coverage and depth; GL's fixed-function stencil, depth compare,
// scissor and clears do the rest, as they do the same thing on every conforming driver.

#include "recode/backends/gl_exact_device.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exact_program.hpp"
#include "gl_context.hpp"
#include "gl_enums.hpp"
#include "gl_functions.hpp"
#include "recode/backends/exact_depth.hpp"
#include "recode/backends/exact_proxy.hpp"
#include "recode/backends/proxy_cache.hpp"
#include "recode/backends/summary_layout.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"

namespace recode::backends {

namespace {

using raster::PixelRect;

// The depth buffer holds q 2^-24 for the contract's 24-bit q: exact in a 32-bit float, and
// ordered as q is, so GL's float depth compare is the contract's integer compare.
constexpr double kDepthUnit = 1.0 / 16777216.0;

std::unique_ptr<detail::GlContext> makeContext(GlPlatform platform, GlPlatform& chosen) {
  std::string eglFailure;
  if (platform == GlPlatform::Egl || platform == GlPlatform::Auto) {
#ifdef RECODE_HAVE_EGL
    try {
      chosen = GlPlatform::Egl;
      return detail::makeEglHeadlessContext();
    } catch (const std::runtime_error& e) {
      if (platform == GlPlatform::Egl)
        throw;
      eglFailure = e.what();
    }
#else
    if (platform == GlPlatform::Egl)
      throw std::runtime_error(
          "GL exact device: this build has no EGL (Debian: apt-get install "
          "libegl-dev, then reconfigure)");
#endif
  }
#ifdef RECODE_HAVE_OSMESA
  chosen = GlPlatform::OsMesa;
  return detail::makeOsMesaCoreContext();
#else
  throw std::runtime_error(
      "GL exact device: this build has no OSMesa (Debian: apt-get install "
      "libosmesa6-dev, then reconfigure)" +
      (eglFailure.empty() ? std::string() : "; EGL: " + eglFailure));
#endif
}

}  // namespace

// What every device of one platform shares, made once per process: the context (a headless
// one needs no size), the function table, the compiled program and the proxy input. Shader
// compilation dominates a device's start-up, and verification creates a device per pair.
// Deliberately never destroyed: tearing a driver down during static destruction is a known
// source of crashes at exit.
struct SharedGl {
  GlPlatform platform = GlPlatform::Auto;
  std::unique_ptr<detail::GlContext> context;
  detail::GlCoreFunctions gl;
  GLuint program = 0;
  GLuint summaryProgram = 0;  // made by the first summary
  GLint framebufferSizeUniform = -1;
  GLuint vertexArray = 0;
  GLuint proxyBuffer = 0;
  const void* owner = nullptr;  // the device whose framebuffer and state are bound now
  // Read-backs into pixel-pack buffers of every device on this context, waited for by the next
  // finish() of any of them: glReadPixels into a buffer returns at once, and the first
  // glGetBufferSubData waits for everything before it.
  struct PendingCopy {
    GLuint buffer = 0;
    std::size_t bytes = 0;
    std::function<void(std::vector<std::uint8_t>)> deliver;
  };
  std::vector<PendingCopy> pending;

  // A GL error is a bug in this device (every input was validated), so it is reported loudly.
  void check(const char* what) const { detail::throwOnGlError(gl, "GL exact device", what); }

  // The proxy records as per-instance attributes, in the layout of ProxyTriangle.
  void createProxyInput() {
    gl.GenVertexArrays(1, &vertexArray);
    gl.BindVertexArray(vertexArray);
    gl.GenBuffers(1, &proxyBuffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, proxyBuffer);
    constexpr GLsizei stride = sizeof(ProxyTriangle);
    const auto offset = [](std::size_t bytes) { return reinterpret_cast<const void*>(bytes); };
    const auto integers = [&](GLuint location, GLint count, std::size_t at) {
      gl.VertexAttribIPointer(location, count, GL_INT, stride, offset(at));
      gl.VertexAttribDivisor(location, 1);
      gl.EnableVertexAttribArray(location);
    };
    integers(0, 4, offsetof(ProxyTriangle, pixelRect));
    integers(1, 4, offsetof(ProxyTriangle, fixedV0V1));
    integers(2, 2, offsetof(ProxyTriangle, fixedV2));
    gl.VertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(ProxyTriangle, z)));
    gl.VertexAttribDivisor(3, 1);
    gl.EnableVertexAttribArray(3);
    integers(4, 1, offsetof(ProxyTriangle, frontFacing));
    gl.VertexAttribIPointer(5, 4, GL_UNSIGNED_INT, stride,
                            offset(offsetof(ProxyTriangle, slopeBits)));
    gl.VertexAttribDivisor(5, 1);
    gl.EnableVertexAttribArray(5);
  }

  // What no device changes: both tests always on ("off" is ALWAYS), culling done on the CPU
  // where the facing is exact, no colour, the scissor always on, the program bound.
  void setFixedState() {
    gl.Enable(GL_DEPTH_TEST);
    gl.Enable(GL_STENCIL_TEST);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_DEPTH_CLAMP);
    gl.Disable(GL_MULTISAMPLE);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.UseProgram(program);
    framebufferSizeUniform = gl.GetUniformLocation(program, "framebufferSize");
  }

  explicit SharedGl(GlPlatform requested) {
    context = makeContext(requested, platform);
    context->makeCurrent();
    gl = detail::loadGlCoreFunctions(*context);
    program = detail::buildExactProgram(gl);
    createProxyInput();
    setFixedState();
    check("setup");
  }

  // The shared state for a platform (Auto resolves once, to whatever it found first).
  static SharedGl& of(GlPlatform requested) {
    static SharedGl* instances[3] = {nullptr, nullptr, nullptr};
    SharedGl*& slot = instances[static_cast<int>(requested)];
    if (slot == nullptr)
      slot = new SharedGl(requested);
    return *slot;
  }
};

struct GlExactDevice::Impl {
  int width = 0;
  int height = 0;
  SharedGl* shared = nullptr;
  const raster::RenderState* state = nullptr;  // the device's (RenderStateDevice::state_)
  GLuint framebuffer = 0;
  GLuint depthStencil = 0;
  raster::TransferCounters transfers;  // what this device's calls waited for and read
  ProxyCache proxyCache;               // the proxies of the blocks drawn last

  // Draws `proxies` in the state set.
  void drawProxies(const std::vector<ProxyTriangle>& proxies) {
    if (proxies.empty())
      return;
    use();
    gl().BufferData(GL_ARRAY_BUFFER,
                    static_cast<GLsizeiptr>(proxies.size() * sizeof(ProxyTriangle)), proxies.data(),
                    GL_STREAM_DRAW);
    // Instances are drawn in order and GL keeps primitive order per pixel, so triangles reach
    // each pixel in index order as the contract requires. The two halves of one proxy
    // rectangle share an edge, which GL's own fill rule hands to exactly one of them.
    constexpr std::size_t kMaxInstances = 1u << 30;
    for (std::size_t first = 0; first < proxies.size(); first += kMaxInstances) {
      const std::size_t count = std::min(kMaxInstances, proxies.size() - first);
      if (first > 0) {
        gl().BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(count * sizeof(ProxyTriangle)),
                        proxies.data() + first, GL_STREAM_DRAW);
      }
      gl().DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count));
    }
    shared->check("drawTriangles");
  }

  const detail::GlCoreFunctions& gl() const { return shared->gl; }

  // Makes the context current and binds this device's framebuffer and state, unless it is
  // the one bound already; every public entry point starts here.
  void use() {
    shared->context->makeCurrent();
    if (shared->owner == this)
      return;
    const auto& g = gl();
    g.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    g.Viewport(0, 0, width, height);
    g.Uniform2f(shared->framebufferSizeUniform, static_cast<GLfloat>(width),
                static_cast<GLfloat>(height));
    const raster::PixelRect& r = state->scissor;
    g.Scissor(r.x0, r.y0, r.width(), r.height());
    g.DepthFunc(detail::glCompareEnum(state->depthFunc));
    g.DepthMask(state->depthWrite ? GL_TRUE : GL_FALSE);
    g.StencilFunc(detail::glCompareEnum(state->stencilFunc), state->stencilRef,
                  state->stencilValueMask);
    applyStencilOps(GL_FRONT, state->frontOps);
    applyStencilOps(GL_BACK, state->backOps);
    g.StencilMask(state->stencilWriteMask);
    shared->owner = this;
  }

  void applyStencilOps(GLenum face, const raster::StencilOps& ops) const {
    gl().StencilOpSeparate(face, detail::glStencilOpEnum(ops.stencilFail),
                           detail::glStencilOpEnum(ops.depthFail),
                           detail::glStencilOpEnum(ops.depthPass));
  }

  void requireLimits() const {
    GLint renderbuffer = 0;
    GLint viewport[2] = {0, 0};
    gl().GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    gl().GetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    if (renderbuffer < width || renderbuffer < height || viewport[0] < width ||
        viewport[1] < height) {
      throw std::runtime_error(
          "GL exact device: the driver's largest renderbuffer (" + std::to_string(renderbuffer) +
          ") or viewport (" + std::to_string(viewport[0]) + "x" + std::to_string(viewport[1]) +
          ") is smaller than " + std::to_string(width) + "x" + std::to_string(height));
    }
  }

  // A framebuffer object with one DEPTH32F_STENCIL8 renderbuffer and no colour, cleared as
  // CpuDevice starts: depth 2^24 - 1 (stored as (2^24 - 1) 2^-24), stencil 0.
  void createFramebuffer() {
    const auto& g = gl();
    const detail::DepthStencilFramebuffer made = detail::createDepthStencilFramebuffer(
        g, GL_DEPTH32F_STENCIL8, "DEPTH32F_STENCIL8", width, height, "GL exact device");
    framebuffer = made.framebuffer;
    depthStencil = made.renderbuffer;
    shared->owner = nullptr;
    use();
    g.ClearDepth(static_cast<double>(raster::kDepthMax) * kDepthUnit);
    g.ClearStencil(0);
    g.Clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }

  // Records a read of `r` in `format`/`type` (`texel` bytes a pixel) into a new pack buffer.
  void readLater(const raster::PixelRect& r, GLenum format, GLenum type, std::size_t texel,
                 std::function<void(std::vector<std::uint8_t>)> deliver) {
    use();
    SharedGl::PendingCopy copy;
    copy.bytes = static_cast<std::size_t>(r.area()) * texel;
    copy.deliver = std::move(deliver);
    const auto& g = gl();
    g.GenBuffers(1, &copy.buffer);
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, copy.buffer);
    g.BufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(copy.bytes), nullptr,
                 GL_STREAM_READ);
    // Rows from the bottom (y = r.y0) up, the interface's order; the scissor does not apply.
    g.ReadPixels(r.x0, r.y0, r.width(), r.height(), format, type, nullptr);
    g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    transfers.readbackBytes += static_cast<long long>(copy.bytes);
    shared->pending.push_back(std::move(copy));
    shared->check("read-back");
  }

  // Waits for the pending read-backs of every device on the context and delivers them, each
  // its own buffer deleted; the first error is passed on once every buffer is gone.
  void finish() {
    if (shared->pending.empty())
      return;
    use();
    std::vector<SharedGl::PendingCopy> copies = std::move(shared->pending);
    shared->pending.clear();
    ++transfers.submissions;
    const auto waiting = std::chrono::steady_clock::now();
    std::exception_ptr error;
    const auto& g = gl();
    for (SharedGl::PendingCopy& copy : copies) {
      std::vector<std::uint8_t> bytes(copy.bytes);
      g.BindBuffer(GL_PIXEL_PACK_BUFFER, copy.buffer);
      g.GetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(copy.bytes),
                         bytes.data());
      g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
      g.DeleteBuffers(1, &copy.buffer);
      try {
        shared->check("finish");
        copy.deliver(std::move(bytes));
      } catch (...) {
        if (!error)
          error = std::current_exception();
      }
    }
    transfers.waitUs +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - waiting)
            .count();
    if (error)
      std::rethrow_exception(error);
  }

  ~Impl() {
    if (shared == nullptr || framebuffer == 0)
      return;
    try {
      shared->context->makeCurrent();
      finish();  // other devices' read-backs may be pending beside this one's
      gl().DeleteFramebuffers(1, &framebuffer);
      gl().DeleteRenderbuffers(1, &depthStencil);
      if (shared->owner == this)
        shared->owner = nullptr;
    } catch (...) {
      // Nothing sensible to do in a destructor; the objects die with the context.
    }
  }
};

namespace {

// A buffer object on the context, deleted with this (GL defers the deletion while commands use
// it).
class GlBuffer {
 public:
  GlBuffer(SharedGl& shared, std::size_t bytes, const void* data, GLenum usage) : shared_(shared) {
    shared_.gl.GenBuffers(1, &name_);
    shared_.gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, name_);
    shared_.gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
    shared_.gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  }
  ~GlBuffer() {
    if (name_ != 0) {
      shared_.context->makeCurrent();
      shared_.gl.DeleteBuffers(1, &name_);
    }
  }
  GlBuffer(const GlBuffer&) = delete;
  GlBuffer& operator=(const GlBuffer&) = delete;
  [[nodiscard]] GLuint name() const { return name_; }
  // Hands the buffer over (to a pending read-back, which deletes it).
  [[nodiscard]] GLuint release() { return std::exchange(name_, 0); }

 private:
  SharedGl& shared_;
  GLuint name_ = 0;
};

// A depth an exact GL device read into a buffer object for its next summary.
class GlKeptDepth final : public raster::KeptDepth {
 public:
  GlKeptDepth(SharedGl& shared, const void* keeper, const PixelRect& over)
      : KeptDepth(keeper, over),
        buffer(shared, 4 * static_cast<std::size_t>(over.area()), nullptr, GL_STREAM_COPY) {}
  GlBuffer buffer;
};

}  // namespace

GlPlatform resolveGlPlatform(GlPlatform requested) {
  return SharedGl::of(requested).platform;
}

GlExactDevice::GlExactDevice(int width, int height, GlPlatform platform)
    : RenderStateDevice(width, height), impl_(std::make_unique<Impl>()) {
  raster::checkFramebufferSize(width, height);
  Impl& d = *impl_;
  d.width = width;
  d.height = height;
  d.state = &state_;
  d.shared = &SharedGl::of(platform);
  d.shared->context->makeCurrent();
  d.requireLimits();
  d.createFramebuffer();
  d.shared->check("device setup");
}

GlExactDevice::~GlExactDevice() = default;

int GlExactDevice::width() const {
  return impl_->width;
}

int GlExactDevice::height() const {
  return impl_->height;
}

std::string GlExactDevice::renderer() const {
  return impl_->shared->context->renderer();
}

GlPlatform GlExactDevice::platform() const {
  return impl_->shared->platform;
}

// RenderStateDevice's setters have stored the change (a device re-applies its whole state when
// it binds again after another device of the process used the shared context); it is set on
// GL here. The cull mode is applied on the CPU, where the facing is exact.
void GlExactDevice::stateChanged(StateChange change, raster::Face face) {
  if (change == StateChange::CullMode)
    return;
  Impl& d = *impl_;
  d.use();
  const detail::GlCoreFunctions& g = d.gl();
  switch (change) {
    case StateChange::Scissor: {
      const PixelRect& r = state_.scissor;
      g.Scissor(r.x0, r.y0, r.width(), r.height());
      return;
    }
    case StateChange::DepthFunc:
      g.DepthFunc(detail::glCompareEnum(state_.depthFunc));
      return;
    case StateChange::DepthWriteMask:
      g.DepthMask(state_.depthWrite ? GL_TRUE : GL_FALSE);
      return;
    case StateChange::StencilFunc:  // one func for both faces, as in the interface
      g.StencilFunc(detail::glCompareEnum(state_.stencilFunc), state_.stencilRef,
                    state_.stencilValueMask);
      return;
    case StateChange::StencilOps:
      d.applyStencilOps(detail::glFaceEnum(face),
                        face == raster::Face::Back ? state_.backOps : state_.frontOps);
      return;
    case StateChange::StencilWriteMask:
      g.StencilMask(state_.stencilWriteMask);
      return;
    case StateChange::CullMode:
      return;
  }
}

void GlExactDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  Impl& d = *impl_;
  d.use();
  // The contract's quantisation, stored as the shaders store fragment depth. GL applies the
  // scissor and the depth write mask to the clear.
  d.gl().ClearDepth(static_cast<double>(raster::quantizeDepth(depth)) * kDepthUnit);
  d.gl().Clear(GL_DEPTH_BUFFER_BIT);
}

void GlExactDevice::clearStencil(std::uint8_t value) {
  Impl& d = *impl_;
  d.use();
  d.gl().ClearStencil(value);  // the stencil write mask applies to the clear
  d.gl().Clear(GL_STENCIL_BUFFER_BIT);
}

void GlExactDevice::drawTriangles(std::span<const raster::WindowVertex> vertices,
                                  std::span<const std::uint32_t> indices) {
  impl_->drawProxies(buildProxyTriangles(vertices, indices, state_));
}

void GlExactDevice::drawMesh(const raster::TriangleSource& source) {
  // As CpuDevice: only the triangles that meet the scissor (the others would give no proxy),
  // set up once for every pass that draws the block under that scissor (proxy_cache.hpp).
  Impl& d = *impl_;
  d.drawProxies(*d.proxyCache.proxies(source, state_).list);
}

raster::PendingRead<std::uint8_t> GlExactDevice::readStencilLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint8_t>::ready({});
  raster::PendingRead<std::uint8_t> read = raster::PendingRead<std::uint8_t>::waiting();
  d.readLater(r, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 1,
              [read](std::vector<std::uint8_t> bytes) mutable { read.deliver(std::move(bytes)); });
  return read;
}

raster::PendingRead<std::uint32_t> GlExactDevice::readDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint32_t>::ready({});
  raster::PendingRead<std::uint32_t> read = raster::PendingRead<std::uint32_t>::waiting();
  d.readLater(r, GL_DEPTH_COMPONENT, GL_FLOAT, 4, [read](std::vector<std::uint8_t> bytes) mutable {
    read.deliver(depthFromStoredFloats(bytes, "GL exact device"));
  });
  return read;
}

std::shared_ptr<const raster::KeptDepth> GlExactDevice::keepDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (!summarisedOnDevice(r))
    return DepthStencilDevice::keepDepthLater(r);
  d.use();
  auto kept = std::make_shared<GlKeptDepth>(*d.shared, impl_.get(), r);
  const auto& g = d.gl();
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, kept->buffer.name());
  g.ReadPixels(r.x0, r.y0, r.width(), r.height(), GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  d.shared->check("keepDepthLater");
  return kept;
}

raster::PendingRead<raster::PixelSummary> GlExactDevice::summarizeLater(
    const PixelRect& rect, const raster::StencilClasses& classes,
    const raster::KeptDepth* nearEnd) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  const auto* kept = dynamic_cast<const GlKeptDepth*>(nearEnd);
  if (kept == nullptr && (nearEnd != nullptr || !summarisedOnDevice(r)))
    return DepthStencilDevice::summarizeLater(r, classes, nearEnd);  // kept on the host, if any
  if (kept != nullptr)
    kept->requireKeptBy(impl_.get(), r);
  raster::requireStencilClasses(classes, "summarizeLater");
  SharedGl& shared = *d.shared;
  const auto& g = d.gl();
  d.use();
  if (shared.summaryProgram == 0)
    shared.summaryProgram = detail::buildSummaryProgram(g);
  const bool withDepth = kept != nullptr;
  const SummaryInputs layout(r, withDepth);
  GlBuffer inputs(shared, layout.bytes(), nullptr, GL_STREAM_COPY);
  const auto at = [](std::size_t offset) { return reinterpret_cast<void*>(offset); };
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, inputs.name());
  g.ReadPixels(r.x0, r.y0, r.width(), r.height(), GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, at(0));
  if (withDepth)
    g.ReadPixels(r.x0, r.y0, r.width(), r.height(), GL_DEPTH_COMPONENT, GL_FLOAT,
                 at(layout.farOffset()));
  g.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, inputs.name());
  g.BufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(layout.tableOffset()),
                  static_cast<GLsizeiptr>(layout.tableBytes), classes.classOf.data());
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // One summary a dispatch, every buffer its own: offsets 0; glReadPixels's rows run from y0 up.
  const SummaryParameters parameters = summaryParameters(r, classes, withDepth, true, 0, 0, 0);
  GlBuffer parameterBuffer(shared, sizeof parameters, &parameters, GL_STREAM_DRAW);
  GlBuffer results(shared, raster::kPixelSummaryBytes, nullptr, GL_STREAM_READ);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, withDepth ? kept->buffer.name() : inputs.name());
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, inputs.name());
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, results.name());
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, parameterBuffer.name());
  g.UseProgram(shared.summaryProgram);
  g.DispatchCompute(1, 1, 1);
  g.UseProgram(shared.program);
  // The shader's writes before the read-back of its words.
  g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  for (GLuint binding = 0; binding < 4; ++binding)
    g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  shared.check("summarizeLater");
  raster::PendingRead<raster::PixelSummary> read =
      raster::PendingRead<raster::PixelSummary>::waiting();
  SharedGl::PendingCopy copy;
  copy.buffer = results.release();
  copy.bytes = raster::kPixelSummaryBytes;
  copy.deliver = [read, r, withDepth](std::vector<std::uint8_t> bytes) mutable {
    read.deliver({summaryFromBytes(bytes.data(), r, withDepth, "GL exact device")});
  };
  d.transfers.readbackBytes += static_cast<long long>(raster::kPixelSummaryBytes);
  shared.pending.push_back(std::move(copy));
  return read;
}

void GlExactDevice::finish() {
  impl_->finish();
}

bool GlExactDevice::defers() const {
  return true;
}

raster::TransferCounters GlExactDevice::transfers() const {
  return impl_->transfers;
}

std::vector<std::uint8_t> GlExactDevice::readStencil(const PixelRect& rect) const {
  // The interface's read-backs are const; waiting for the queued commands changes no state it
  // shows.
  auto& self = const_cast<GlExactDevice&>(*this);
  raster::PendingRead<std::uint8_t> read = self.readStencilLater(rect);
  self.finish();
  return read.take();
}

std::vector<std::uint32_t> GlExactDevice::readDepth(const PixelRect& rect) const {
  auto& self = const_cast<GlExactDevice&>(*this);
  raster::PendingRead<std::uint32_t> read = self.readDepthLater(rect);
  self.finish();
  return read.take();
}

}  // namespace recode::backends
