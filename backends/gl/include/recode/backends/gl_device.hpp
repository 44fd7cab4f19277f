#pragma once
// The depth/stencil device on real OpenGL's fixed-function pipeline, off screen: through OSMesa
// (Mesa's llvmpipe) or a headless EGL context (Mesa's surfaceless platform, or a GPU driver's EGL
// device). It takes the same command stream as raster::CpuDevice, so replaying one stream on both
// compares the reference with a real GL implementation's own depth arithmetic
// (recode/verify/gl_parity.hpp). No GL type appears here.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "recode/backends/gl_platform.hpp"
#include "recode/raster/render_state_device.hpp"

namespace recode::backends {

namespace detail {
class GlContext;
}

class GlDevice final : public raster::RenderStateDevice {
 public:
  // A framebuffer of width x height pixels with a 24-bit depth and an 8-bit stencil buffer,
  // cleared to depth 1.0 and stencil 0, in GL's default state (docs/rasterization.md,
  // section 6). Throws std::invalid_argument unless 1 <= width, height <= 16384, and
  // std::runtime_error when the GL context cannot be created or lacks what the device needs.
  //
  // Each device owns its own context and makes it current on the calling thread before every
  // GL call, so several devices may live in one process and be used in turns. A device must be
  // used by one thread at a time (a GL context is current on one thread).
  // `platform`: OsMesa, Egl (a compatibility-profile context; the device draws into a
  // framebuffer object of its own), or Auto (OSMesa when this build has it, else EGL). A platform
  // this build lacks is a std::runtime_error naming what to install.
  GlDevice(int width, int height, GlPlatform platform = GlPlatform::Auto);
  ~GlDevice() override;
  GlDevice(const GlDevice&) = delete;
  GlDevice& operator=(const GlDevice&) = delete;

  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }

  // The state setters are RenderStateDevice's; stateChanged sets each change on GL.
  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  // Validated exactly as CpuDevice validates (same std::invalid_argument cases) before
  // anything reaches GL. x and y are snapped to the 1/256-pixel grid here, round half to even,
  // so GL starts from the same fixed-point vertices as the reference.
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override;
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override;
  // Each read-back is a wait for the commands before it: one submission, and its bytes.
  [[nodiscard]] raster::TransferCounters transfers() const override;

  // GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15, 256 bits)".
  [[nodiscard]] std::string renderer() const;
  // The platform the context came from (OsMesa or Egl).
  [[nodiscard]] GlPlatform platform() const;

 private:
  void stateChanged(StateChange change, raster::Face face) override;
  void applyCullMode(raster::CullMode mode);

  struct Impl;
  int width_;
  int height_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace recode::backends
