#pragma once
// The seam between the RECODE algorithm and a depth/stencil machine: a small subset of
// OpenGL's per-fragment pipeline, expressed as plain commands. Every back end (the CPU
// reference, fixed-function OpenGL, the exact OpenGL and Vulkan devices) implements this
// interface, so the same command stream runs on all of them. The exact semantics are in
// docs/rasterization.md.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "recode/raster/pending_read.hpp"
#include "recode/raster/pixel_summary.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/triangle_source.hpp"
#include "recode/raster/window_vertex.hpp"

namespace recode::raster {

// What a device has handed to hardware and back since it was made: the cost a GPU pays per
// frame beyond its drawing. A device that runs on the CPU counts nothing.
struct TransferCounters {
  long long submissions = 0;    // command submissions waited on
  long long readbackBytes = 0;  // bytes copied from device memory to the host
  // Microseconds the host spent blocked until the device had run what was submitted (and,
  // where the API waits inside the read, read it back): of a frame's time, what the device
  // took rather than the host's own work of recording the commands and using their results.
  double waitUs = 0.0;
  // Compute dispatches recorded (the vulkan-compute device's stages; 0 where a device draws
  // through a graphics pipeline or on the CPU).
  long long dispatches = 0;
  // The vulkan-compute device's stage groups that stageUs times.
  static constexpr std::size_t kStages = 5;
  // Their names, as the CSV columns stage_ms_NAME give them.
  static constexpr std::array<const char*, kStages> kStageNames = {"vertex", "setup", "binning",
                                                                   "raster", "reads"};
  // Device time of the vulkan-compute device's stages, in microseconds, from timestamp
  // queries, in the order of kStageNames (0 where nothing measures them).
  std::array<double, kStages> stageUs{};

  // Adds `other`'s counts to these.
  TransferCounters& operator+=(const TransferCounters& other) {
    submissions += other.submissions;
    readbackBytes += other.readbackBytes;
    waitUs += other.waitUs;
    dispatches += other.dispatches;
    for (std::size_t k = 0; k < kStages; ++k)
      stageUs[k] += other.stageUs[k];
    return *this;
  }
  // What was counted between `earlier` and this.
  [[nodiscard]] TransferCounters since(const TransferCounters& earlier) const {
    TransferCounters d = *this;
    d.submissions -= earlier.submissions;
    d.readbackBytes -= earlier.readbackBytes;
    d.waitUs -= earlier.waitUs;
    d.dispatches -= earlier.dispatches;
    for (std::size_t k = 0; k < kStages; ++k)
      d.stageUs[k] -= earlier.stageUs[k];
    return d;
  }
};

// A depth over a rectangle kept by keepDepthLater for a later summarizeLater; what it holds
// (values on the host, or a region of the device's own memory) is the device's affair. It
// remembers who kept it and over which rectangle, since it serves only that summary.
class KeptDepth {
 public:
  // A depth `keeper` (the device, or what it identifies itself by) kept over `rect`.
  KeptDepth(const void* keeper, const PixelRect& rect) : keeper_(keeper), rect_(rect) {}
  virtual ~KeptDepth() = default;
  KeptDepth(const KeptDepth&) = delete;
  KeptDepth& operator=(const KeptDepth&) = delete;

  // Throws std::invalid_argument unless `keeper` kept it over `rect` (summarizeLater's check).
  void requireKeptBy(const void* keeper, const PixelRect& rect) const;

 private:
  const void* keeper_;
  PixelRect rect_;
};

// A framebuffer of width() x height() pixels with a 24-bit depth and an 8-bit stencil value
// per pixel, and the commands RECODE draws with. Implementations: raster::CpuDevice (the
// bit-exact reference) and the GL and Vulkan devices of backends/; a DevicePool's factory makes
// them for the collision API.
class DepthStencilDevice {
 public:
  virtual ~DepthStencilDevice() = default;

  // Framebuffer width in pixels, fixed when the device is made.
  [[nodiscard]] virtual int width() const = 0;
  // Framebuffer height in pixels, fixed when the device is made.
  [[nodiscard]] virtual int height() const = 0;

  // Drawing, clears and read-backs are all limited to the scissor rectangle (half-open,
  // in pixels). The default is the whole framebuffer; a rectangle is clamped to it.
  virtual void setScissor(const PixelRect& rect) = 0;

  // Clear depth (quantised like fragment depth) / stencil inside the scissor. As in GL, the
  // depth write mask and the stencil write mask apply to clears too.
  virtual void clearDepth(double depth) = 0;
  // Sets the stencil inside the scissor to `value` (bits outside the write mask kept).
  virtual void clearStencil(std::uint8_t value) = 0;

  // The depth test: a fragment passes when func(fragment depth, stored depth) holds.
  virtual void setDepthFunc(CompareFunc func) = 0;
  // Whether fragments that pass the tests (and clears) write depth.
  virtual void setDepthWriteMask(bool write) = 0;

  // The stencil test: passes when func(ref & valueMask, stored & valueMask) holds.
  virtual void setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) = 0;
  virtual void setStencilOps(Face face, const StencilOps& ops) = 0;  // face Front, Back or Both
  // The stencil bits that stencil operations and clears may change.
  virtual void setStencilWriteMask(std::uint8_t mask) = 0;

  // Which triangles are discarded by their winding in window coordinates.
  virtual void setCullMode(CullMode mode) = 0;

  // Draws indexed triangles (three indices each). Throws std::invalid_argument for an index
  // out of range, an index count that is not a multiple of three, or a vertex that is not
  // finite, lies beyond kMaxWindowCoordinate, or has z outside [0, 1].
  virtual void drawTriangles(std::span<const WindowVertex> vertices,
                             std::span<const std::uint32_t> indices) = 0;

  // Draws a whole block: by definition drawTriangles(source.allTriangles()), which is what this
  // default does, so a device that does not override it sees the same commands as before. A
  // device may instead draw only source.trianglesMeeting(its scissor): the triangles left out
  // cover no pixel centre inside the scissor, so the buffers come out the same bits (CpuDevice
  // does this, so a pair's cost follows its MOR rather than its meshes).
  virtual void drawMesh(const TriangleSource& source) {
    const TriangleDraw draw = source.allTriangles();
    drawTriangles(draw.vertices, draw.indices);
  }

  // Read-backs over a rectangle (clamped to the framebuffer, not to the scissor), row-major,
  // rows from the bottom (y = rect.y0) up, as glReadPixels returns them. Depth values are
  // 24-bit unsigned normalised integers in [0, 2^24 - 1].
  [[nodiscard]] virtual std::vector<std::uint8_t> readStencil(const PixelRect& rect) const = 0;
  // The depth values over `rect`, laid out as readStencil's.
  [[nodiscard]] virtual std::vector<std::uint32_t> readDepth(const PixelRect& rect) const = 0;

  // Read-backs that may wait: readStencil(rect) and readDepth(rect) as the buffers are after
  // the commands given so far, delivered by the time finish() returns. The defaults read at
  // once. A device that defers() records commands and read-backs and runs them when finish()
  // is called (or when a plain read-back needs them), so that a batch of pair tests costs one
  // submission (core::collidePairs).
  [[nodiscard]] virtual PendingRead<std::uint8_t> readStencilLater(const PixelRect& rect) {
    return PendingRead<std::uint8_t>::ready(readStencil(rect));
  }
  // The depth values over `rect` as they are after the commands so far (readDepth's layout).
  [[nodiscard]] virtual PendingRead<std::uint32_t> readDepthLater(const PixelRect& rect) {
    return PendingRead<std::uint32_t>::ready(readDepth(rect));
  }
  // Summaries (pixel_summary.hpp), for callers that need counts and extremes rather than
  // pixels: a GPU device may reduce its buffers itself, so that only kPixelSummaryBytes come
  // back. The defaults read the buffers back (readStencilLater, readDepthLater) and summarise
  // on the host when they arrive: the same values, the plain read-backs' cost.
  //
  // Keeps the depth over `rect` as it is after the commands so far, for summarizeLater.
  [[nodiscard]] virtual std::shared_ptr<const KeptDepth> keepDepthLater(const PixelRect& rect);
  // summarizePixels over `rect` of the stencil as it is after the commands so far, with
  // `nearEnd`'s depths (kept by this device over the same rectangle; null: no depth interval)
  // and the depth now as the far end. `rect` is clamped to the framebuffer. Throws
  // std::invalid_argument for a KeptDepth of another device or rectangle, or a bad class table.
  [[nodiscard]] virtual PendingRead<PixelSummary> summarizeLater(const PixelRect& rect,
                                                                 const StencilClasses& classes,
                                                                 const KeptDepth* nearEnd);

  // Runs every command given so far and delivers every pending read-back.
  virtual void finish() {}
  // Whether commands wait for finish(): then a read-back that waits costs nothing until then,
  // and one that does not costs a round trip to the hardware.
  [[nodiscard]] virtual bool defers() const { return false; }
  // Submissions and read-back bytes so far (TransferCounters).
  [[nodiscard]] virtual TransferCounters transfers() const { return {}; }
};

}  // namespace recode::raster
