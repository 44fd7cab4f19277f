#pragma once
// The vulkan-compute device: the rasterization contract (docs/rasterization.md) as a tile
// rasterizer in Vulkan compute shaders only: no graphics pipeline, no render pass, no
// depth/stencil image (docs/backends.md, "The compute device"). The depth q and the stencil live
// in a storage buffer, a word a pixel. Its clears, draws and reads are not run one by one: they
// join the frame that every compute device of the process shares, a job list run just before
// the submission as a fixed number of dispatches whatever it holds (vertex, set-up, binning,
// raster, resolve). Its commands are cut into epochs, runs that start by clearing what they use
// (a pair test's), and every 8x8 block of every epoch is drawn at once, in command order, each
// block's list in index order, so its buffers match raster::CpuDevice bit for bit. The host
// validates a draw and hands over its window vertices and indices as they are, once per
// TriangleSource::contentKey; a posed block's object-space mesh stays on the device, and its
// draws take only the pose and the view. It shares the exact Vulkan device's 64-bit context and
// recording: a frame's commands of every Vulkan device go in one submission. No Vulkan type
// appears here.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "recode/raster/posed_boxes.hpp"
#include "recode/raster/render_state_device.hpp"

namespace recode::backends {

class VulkanComputeDevice final : public raster::RenderStateDevice, public raster::PosedBoxReducer {
 public:
  // A width x height framebuffer (depth 2^24 - 1, stencil 0, the interface's default state).
  // Throws std::invalid_argument unless 1 <= width, height <= 16384, and std::runtime_error
  // when there is no Vulkan driver or no physical device with what it needs (Vulkan 1.3,
  // shaderFloat64, shaderInt64 and VK_KHR_push_descriptor), saying what is missing.
  VulkanComputeDevice(int width, int height);
  ~VulkanComputeDevice() override;
  VulkanComputeDevice(const VulkanComputeDevice&) = delete;
  VulkanComputeDevice& operator=(const VulkanComputeDevice&) = delete;

  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;

  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  // Validated exactly as CpuDevice validates (raster::checkDraw), then uploaded as it is and
  // drawn on the device.
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  // A posed block (TriangleSource::posedMesh): its object-space mesh uploaded once and kept
  // while the source's `alive` has not expired, and per draw only the pose and the view; the
  // vertex stage runs on the device (once per content key), then every triangle is drawn.
  // Any other block: the triangles that meet the scissor (TriangleSource::trianglesMeeting),
  // uploaded once for every later draw of the same content key under a scissor inside that one.
  void drawMesh(const raster::TriangleSource& source) override;
  // Posed blocks' world boxes on the device (the frame's box stage, tile_box.comp, a workgroup
  // a block), each block kept as a posed draw keeps it: 64 bytes a block come back.
  [[nodiscard]] raster::PendingRead<raster::PosedBox> posedBoxesLater(
      std::span<const raster::PosedMesh> meshes) override;
  // Each runs everything recorded so far (one submission) and returns the values.
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override;
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override;

  // Recorded, and delivered by finish(): the frame's raster stage writes the rectangle as the
  // commands before it left it, and a copy takes it to host-visible memory.
  [[nodiscard]] raster::PendingRead<std::uint8_t> readStencilLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<std::uint32_t> readDepthLater(
      const raster::PixelRect& rect) override;
  // Summaries on the device, by the Vulkan device's summary shader over copies the frame's
  // raster stage makes at the summary's place in the commands: 64 bytes come back. Rectangles of
  // more than 4 Mi pixels are summarised from plain read-backs instead.
  [[nodiscard]] std::shared_ptr<const raster::KeptDepth> keepDepthLater(
      const raster::PixelRect& rect) override;
  [[nodiscard]] raster::PendingRead<raster::PixelSummary> summarizeLater(
      const raster::PixelRect& rect, const raster::StencilClasses& classes,
      const raster::KeptDepth* nearEnd) override;
  void finish() override;
  [[nodiscard]] bool defers() const override;
  [[nodiscard]] raster::TransferCounters transfers() const override;

  // The physical device's name ("llvmpipe (LLVM 15.0.6, 256 bits)").
  [[nodiscard]] std::string renderer() const;

  // Triangle lists uploaded so far (a new content key, or a scissor its kept list does not
  // cover, or a posed mesh the device did not hold), draws that found their list on the device
  // already, posed draws, and the posed meshes the device holds now (a mesh whose block is gone
  // is let go at the next draw or finish()).
  struct MeshCounters {
    long long uploads = 0;
    long long reuses = 0;
    long long posedDraws = 0;
    long long residentMeshes = 0;
  };
  [[nodiscard]] MeshCounters meshCounters() const;

  // What the rasterizer's first stages made of a draw, for checking each stage against the
  // reference (tests/backends/vulkan/vulkan_compute_device_test.cpp does).
  struct SetUpTriangle {
    std::int32_t fixed[6] = {};  // snapped X0, Y0, X1, Y1, X2, Y2
    bool frontFacing = false;
    raster::PixelRect candidates;  // inside the scissor; empty: the triangle draws nothing
    float z0 = 0.0f;
    double dzdx = 0.0;
    double dzdy = 0.0;
  };
  struct DrawStages {
    raster::PixelRect scissor;
    // The 8x8 blocks of the draw's epoch's grid, from pixel (gridX0, gridY0) (multiples of 8).
    int gridX0 = 0;
    int gridY0 = 0;
    int gridWidth = 0;
    int gridHeight = 0;
    std::vector<SetUpTriangle> triangles;  // the set-up stage's records, in index order
    // Each block's list after the sort stage, row by row, with this draw's entries only (in its
    // own index order); a block whose list did not fit is marked in `overflowed` and drawn from
    // every triangle instead.
    std::vector<std::vector<std::uint32_t>> blockLists;
    std::vector<bool> overflowed;
    // A posed draw's vertex stage: the window vertices it made, one a vertex of the block
    // (empty for a draw of window vertices).
    std::vector<raster::WindowVertex> windowVertices;
  };
  // From now on, the last draw of each frame also copies its stages' outputs back (a debugging
  // aid: it costs a read-back of the frame's work memory); lastDrawStages() runs what is
  // recorded and returns those of the last draw that drew anything. Throws std::logic_error
  // before any such draw.
  void keepDrawStages();
  [[nodiscard]] DrawStages lastDrawStages();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace recode::backends
