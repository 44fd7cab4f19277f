#pragma once
// The reference depth/stencil machine: a 24-bit depth buffer and an 8-bit stencil buffer in
// memory and a RenderState, drawn by the raster pipeline (pipeline.hpp). Single-threaded and
// deterministic.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/raster/draw_recording.hpp"
#include "recode/raster/pipeline.hpp"
#include "recode/raster/pixel_buffer.hpp"
#include "recode/raster/render_state_device.hpp"
#include "recode/raster/state.hpp"

namespace recode::raster {

class CpuDevice final : public RenderStateDevice {
 public:
  // Throws std::invalid_argument unless 1 <= width, height <= kMaxFramebufferSize. Depth
  // starts at 1.0 (2^24 - 1) and stencil at 0, as after GL's default clears.
  CpuDevice(int width, int height);

  // Makes this device what CpuDevice(width, height) makes (buffers, state, counters, no
  // recorded draws), keeping the buffers' memory when it is large enough: a pool serving
  // frames of changing sizes then allocates, and the system maps fresh pages, only for a
  // frame larger than any before. Throws as the constructor does, leaving the device as it was.
  void reshape(int width, int height);

  // Pixels the buffers hold without allocating: the largest size reshape keeps memory for.
  [[nodiscard]] std::size_t pixelCapacity() const {
    return std::min(depth_.data.capacity(), stencil_.data.capacity());
  }

  [[nodiscard]] int width() const override { return depth_.rect.width(); }
  [[nodiscard]] int height() const override { return depth_.rect.height(); }

  // The state setters are RenderStateDevice's.
  void clearDepth(double depth) override;
  void clearStencil(std::uint8_t value) override;
  void drawTriangles(std::span<const WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override;
  // Draws source.trianglesMeeting(scissor) when the source offers it, else the whole block. A
  // source with a content key is recorded when its draw culls nothing, and a later draw of it
  // under a scissor inside the recorded one replays the recording (draw_recording.hpp): the
  // same fragments in the same order, without snapping, setup or traversal. The last two
  // sources drawn are kept (a pair test's two blocks).
  void drawMesh(const TriangleSource& source) override;
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const PixelRect& rect) const override;
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const PixelRect& rect) const override;

  // Direct views of the whole buffers (row-major, bottom row first), for tools and tests.
  [[nodiscard]] std::span<const std::uint8_t> stencilBuffer() const { return stencil_.data; }
  [[nodiscard]] std::span<const std::uint32_t> depthBuffer() const { return depth_.data; }

  // Counters since construction (or the last reset): useful for benchmarks and teaching. The
  // pipeline's count the triangles that were snapped and set up; a replayed draw adds its
  // recorded triangles (those that covered a pixel) to trianglesReplayed instead, and those its
  // cull mode discards to trianglesCulled.
  struct Counters : PipelineCounters {
    std::uint64_t fragments = 0;
    std::uint64_t trianglesReplayed = 0;
  };
  [[nodiscard]] const Counters& counters() const { return counters_; }
  void resetCounters() { counters_ = {}; }

 private:
  // Validates a draw, then runs the pipeline over it into the buffers, and into `recording`
  // when there is one.
  void rasterize(std::span<const WindowVertex> vertices, std::span<const std::uint32_t> indices,
                 DrawRecording* recording);
  void replay(const DrawRecording& recording);

  PixelBuffer<std::uint32_t> depth_;  // the whole framebuffer; its rectangle gives the size
  PixelBuffer<std::uint8_t> stencil_;
  Counters counters_;
  std::array<DrawRecording, 2> recordings_;
  std::size_t nextRecording_ = 0;  // the one the next recorded draw overwrites
};

// Of `devices` (none null), the position of the one to reshape to width x height: the one with
// the least memory that holds that size, else the one with the most (it grows the least);
// devices.size() when there are none.
[[nodiscard]] std::size_t bestDeviceToReshape(std::span<const CpuDevice* const> devices, int width,
                                              int height);

}  // namespace recode::raster
