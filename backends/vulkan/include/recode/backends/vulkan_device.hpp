#pragma once
// The exact Vulkan device: Vulkan 1.3, headless, with the exact GL device's technique
// (docs/backends.md): each triangle is drawn as a proxy rectangle over its candidate pixels and
// the fragment shader applies the rasterization contract (shared GLSL, compiled to SPIR-V at
// build time), writing the contract's 24-bit depth q as q 2^-24 into a D32_SFLOAT_S8_UINT
// attachment. Stencil, the depth compare and the scissor stay fixed-function (dynamic state), so
// its depth and stencil match raster::CpuDevice bit for bit. No Vulkan type appears here.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "recode/backends/vulkan_shader_arithmetic.hpp"
#include "recode/raster/render_state_device.hpp"

namespace recode::backends {

class VulkanDevice final : public raster::RenderStateDevice {
 public:
  // A width x height framebuffer (depth 2^24 - 1, stencil 0, the interface's default state).
  // Throws std::invalid_argument unless 1 <= width, height <= 16384, and std::runtime_error
  // when there is no Vulkan driver or no physical device with what the device needs (Vulkan
  // 1.3, a D32_SFLOAT_S8_UINT depth/stencil attachment, and for Native64 shaderFloat64 and
  // shaderInt64), saying what to install. Every device of the process with the same arithmetic
  // shares one instance, logical device and pipeline, made on first use; a device must be used
  // by one thread at a time.
  VulkanDevice(int width, int height, ShaderArithmetic arithmetic = ShaderArithmetic::Native64);
  ~VulkanDevice() override;
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;

  // The state setters are RenderStateDevice's.
  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  // Validated exactly as CpuDevice validates, set up on the CPU (backends::buildProxyTriangles)
  // and drawn as one instanced draw of proxy rectangles.
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  // Only the triangles that meet the scissor (TriangleSource::trianglesMeeting), as CpuDevice.
  void drawMesh(const raster::TriangleSource& source) override;
  // Each runs everything recorded so far (one submission) and returns the values.
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override;
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override;

  // Commands are recorded into one command buffer and run by finish() (one submission, waited
  // on), or by readStencil or readDepth; these read-backs are recorded and delivered by finish().
  [[nodiscard]] raster::PendingRead<std::uint8_t> readStencilLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<std::uint32_t> readDepthLater(
      const raster::PixelRect& rect) override;
  // Summaries worked out on the GPU (summary_vk.comp): the near end and the buffers are copied
  // into device memory and reduced by a compute shader, and 64 bytes come back. Rectangles of
  // more than 4 Mi pixels are summarised from plain read-backs instead.
  [[nodiscard]] std::shared_ptr<const raster::KeptDepth> keepDepthLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<raster::PixelSummary> summarizeLater(
      const raster::PixelRect& rect, const raster::StencilClasses& classes,
      const raster::KeptDepth* nearEnd) override;
  void finish() override;
  [[nodiscard]] bool defers() const override;
  [[nodiscard]] raster::TransferCounters transfers() const override;

  // The physical device's name ("llvmpipe (LLVM 15.0.6, 256 bits)") and its driver's.
  [[nodiscard]] std::string renderer() const;
  [[nodiscard]] ShaderArithmetic arithmetic() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace recode::backends
