#pragma once
// The exact GL device: OpenGL 4.5 core with shaders that apply the rasterization contract
// themselves (docs/rasterization.md; how, in docs/backends.md), so its depth and stencil match
// raster::CpuDevice bit for bit on any conforming GL driver, where the fixed-function GlDevice
// inherits the driver's own float depth. Each triangle is drawn as a proxy rectangle over its
// candidate pixels; the fragment shader keeps the pixels the contract covers and writes the
// contract's 24-bit depth q as q 2^-24 into a 32-bit float depth buffer. Stencil stays
// fixed-function. No GL type appears here.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "recode/backends/gl_platform.hpp"
#include "recode/raster/render_state_device.hpp"

namespace recode::backends {

class GlExactDevice final : public raster::RenderStateDevice {
 public:
  // A width x height framebuffer (depth 1.0, stencil 0, GL's default state). Throws
  // std::invalid_argument unless 1 <= width, height <= 16384, and std::runtime_error when no
  // context of the platform can be made or it lacks what the device needs (OpenGL 4.5 core,
  // 64-bit integers in shaders, a 16384-pixel renderbuffer), saying which.
  //
  // Devices of a platform share one context (made on first use): use them, and any other GL
  // device of the process, from one thread at a time. Each makes the context current before
  // its GL calls and re-applies its own state after another device used it.
  GlExactDevice(int width, int height, GlPlatform platform = GlPlatform::Auto);
  ~GlExactDevice() override;
  GlExactDevice(const GlExactDevice&) = delete;
  GlExactDevice& operator=(const GlExactDevice&) = delete;

  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;

  // The state setters are RenderStateDevice's; stateChanged sets each change on GL.
  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  // Validated exactly as CpuDevice validates, then snapped, set up (facing, culling, candidate
  // pixels) on the CPU, and drawn as one instanced draw of proxy rectangles.
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  // Only the triangles that meet the scissor (TriangleSource::trianglesMeeting), as CpuDevice.
  void drawMesh(const raster::TriangleSource& source) override;
  // Each waits for the commands before it (and the pending read-backs) and returns the values.
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override;
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override;

  // Read-backs into pixel-pack buffers, which GL fills without the host waiting; finish() of
  // any exact GL device on the same context waits once for all of them (counted as one
  // submission, by the device whose finish() waited) and delivers them.
  [[nodiscard]] raster::PendingRead<std::uint8_t> readStencilLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<std::uint32_t> readDepthLater(
      const raster::PixelRect& rect) override;
  // Summaries worked out by a compute shader (pixel_summary.glsl): the buffers are read into
  // buffer objects on the GPU and reduced there, and 64 bytes come back. Rectangles of more than
  // 4 Mi pixels are summarised from plain read-backs instead.
  [[nodiscard]] std::shared_ptr<const raster::KeptDepth> keepDepthLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<raster::PixelSummary> summarizeLater(
      const raster::PixelRect& rect, const raster::StencilClasses& classes,
      const raster::KeptDepth* nearEnd) override;
  void finish() override;
  [[nodiscard]] bool defers() const override;
  [[nodiscard]] raster::TransferCounters transfers() const override;

  // GL_RENDERER of the context ("llvmpipe (LLVM 15.0.6, 256 bits)") and the platform it came
  // from (never Auto).
  [[nodiscard]] std::string renderer() const;
  [[nodiscard]] GlPlatform platform() const;

 private:
  void stateChanged(StateChange change, raster::Face face) override;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace recode::backends
