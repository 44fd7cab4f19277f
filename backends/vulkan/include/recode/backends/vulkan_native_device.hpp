#pragma once
// The depth/stencil device on Vulkan's own graphics pipeline, headless: the driver rasterizes,
// interpolates depth and converts it to its depth/stencil attachment (D24_UNORM_S8_UINT where the
// driver has it, else D32_SFLOAT_S8_UINT), and the fixed-function depth and stencil tests, ops,
// masks, scissor and culling do the rest; no shader applies the rasterization contract. It takes
// the same command stream as raster::CpuDevice, as the fixed-function GL device does, so
// `recode conform` and the parity tools show where a Vulkan driver departs from the contract.
// Its bits are the driver's: it promises what the Vulkan specification promises, not the
// reference's depth or coverage (docs/backends.md). No Vulkan type appears here.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "recode/raster/render_state_device.hpp"

namespace recode::backends {

class VulkanNativeDevice final : public raster::RenderStateDevice {
 public:
  // A width x height framebuffer (depth 1.0, stencil 0, the interface's default state). Throws
  // std::invalid_argument unless 1 <= width, height <= 16384, and std::runtime_error when there
  // is no Vulkan driver or no physical device with what the device needs (Vulkan 1.3, a
  // depth/stencil attachment with transfers, a viewport as large as the framebuffer), saying
  // what to install. Every native device of the process shares one logical device (the one
  // that asks for no 64-bit shader arithmetic, the vulkan-32 device's), one recording and one
  // pipeline; a device must be used by one thread at a time.
  VulkanNativeDevice(int width, int height);
  ~VulkanNativeDevice() override;
  VulkanNativeDevice(const VulkanNativeDevice&) = delete;
  VulkanNativeDevice& operator=(const VulkanNativeDevice&) = delete;

  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;

  // The state setters are RenderStateDevice's; the state is set as dynamic state on each draw.
  //
  // The clamped value, as a float, cleared by the driver into the scissor (nothing when the
  // depth write mask is off), converted to the attachment's format by the driver.
  void clearDepth(double depth) override;
  // Sets the stencil inside the scissor; under a partial write mask, a masked draw.
  void clearStencil(std::uint8_t value) override;
  // Validated exactly as CpuDevice validates; x and y are snapped to the 1/256-pixel grid on
  // the host (round half to even, as the GL device does) and the indices drawn as an indexed
  // triangle list by the driver, culled by the driver's facing. Nothing under an empty scissor.
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  // Each runs everything recorded so far (one submission) and returns the values: the depth as
  // 24-bit unsigned normalised integers (from D32_SFLOAT_S8_UINT, the float times 2^24 - 1
  // rounded to nearest).
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override;
  // The depth values over `rect`, laid out as readStencil's.
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override;

  // Commands are recorded into the shared recording and run by finish() (one submission, waited
  // on), or by readStencil or readDepth; these read-backs are recorded and delivered by finish().
  [[nodiscard]] raster::PendingRead<std::uint8_t> readStencilLater(
      const raster::PixelRect& rect) override;
  // The depth as readDepth gives it, delivered by finish().
  [[nodiscard]] raster::PendingRead<std::uint32_t> readDepthLater(
      const raster::PixelRect& rect) override;
  void finish() override;
  [[nodiscard]] bool defers() const override;
  [[nodiscard]] raster::TransferCounters transfers() const override;

  // The physical device's name ("llvmpipe (LLVM 15.0.6, 256 bits)").
  [[nodiscard]] std::string renderer() const;
  // The attachment's format: "D24_UNORM_S8_UINT" or "D32_SFLOAT_S8_UINT".
  [[nodiscard]] std::string depthStencilFormat() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace recode::backends
