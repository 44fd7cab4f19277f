#include "recode/raster/cpu_device.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "recode/raster/block_fragments.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/draw_recording.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/fragment_stage.hpp"
#include "recode/raster/invariants.hpp"
#include "recode/raster/pipeline.hpp"

namespace recode::raster {

namespace {

// The fragment stage on the device's buffers: each covered pixel's depth from the triangle's
// plane, then the stencil and depth tests and writes.
class FragmentWriter final : public TriangleSink {
 public:
  FragmentWriter(const RenderState& state, PixelBuffer<std::uint32_t>& depth,
                 PixelBuffer<std::uint8_t>& stencil)
      : state_(state),
        depth_(depth),
        stencil_(stencil),
        frontKernel_(detail::compiledFragmentKernel(state, state.frontOps)),
        backKernel_(detail::compiledFragmentKernel(state, state.backOps)) {}

  void beginTriangle(const TriangleSetup& triangle,
                     const std::array<FixedVertex, 3>& /*snapped*/) override {
    begin(triangle.depth, triangle.frontFacing);
  }

  // The same for a recorded triangle (a replay).
  void begin(const DepthPlane& plane, bool frontFacing) {
    plane_ = &plane;
    ops_ = &state_.opsFor(frontFacing);
    kernel_ = frontFacing ? frontKernel_ : backKernel_;
  }

  void coveredBlock(int blockX, int blockY, std::uint64_t mask) override {
    RECODE_INVARIANT(depth_.contains(blockX, blockY),
                     "covered blocks start inside the framebuffer");
    RECODE_INVARIANT(mask != 0, "covered blocks have a non-empty coverage mask");
    BlockFragments block;
    block.state = &state_;
    block.ops = ops_;
    block.plane = plane_;
    block.x = blockX;
    block.y = blockY;
    // Depth and stencil share the framebuffer's rectangle, so one index serves both.
    const std::size_t origin = depth_.index(blockX, blockY);
    block.depth = depth_.data.data() + origin;
    block.stencil = stencil_.data.data() + origin;
    block.stride = depth_.rect.width();
    block.wholeColumns = blockX + 8 <= depth_.rect.x1;
    block.kernel = kernel_;
    fragments += static_cast<std::uint64_t>(applyBlockFragments(block, mask));
  }

  std::uint64_t fragments = 0;

 private:
  const RenderState& state_;
  PixelBuffer<std::uint32_t>& depth_;
  PixelBuffer<std::uint8_t>& stencil_;
  const DepthPlane* plane_ = nullptr;
  const StencilOps* ops_ = nullptr;
  // The fragment kernels compiled for this draw's state and each facing's ops (the state does
  // not change during a draw), and the current triangle's.
  int frontKernel_ = -1;
  int backKernel_ = -1;
  int kernel_ = -1;
};

// The fragment writer of a draw being recorded: each triangle and block goes to the recording
// too, in the order the writer gets them.
class RecordingWriter final : public TriangleSink {
 public:
  RecordingWriter(FragmentWriter& writer, DrawRecording& recording)
      : writer_(writer), recording_(recording) {}

  void beginTriangle(const TriangleSetup& triangle,
                     const std::array<FixedVertex, 3>& snapped) override {
    recording_.addTriangle(triangle);
    writer_.beginTriangle(triangle, snapped);
  }

  void coveredBlock(int blockX, int blockY, std::uint64_t mask) override {
    recording_.addBlock(blockX, blockY, mask);
    writer_.coveredBlock(blockX, blockY, mask);
  }

 private:
  FragmentWriter& writer_;
  DrawRecording& recording_;
};

}  // namespace

// What a new device is lives in reshape alone, so that a reshaped device cannot drift from it.
CpuDevice::CpuDevice(int width, int height) : RenderStateDevice(width, height) {
  reshape(width, height);
}

void CpuDevice::reshape(int width, int height) {
  checkFramebufferSize(width, height);
  const PixelRect framebuffer{0, 0, width, height};
  const auto area = static_cast<std::size_t>(framebuffer.area());
  // Only the reserves can throw (out of memory), and they change no pixel: the device is then
  // still what it was.
  depth_.data.reserve(area);
  stencil_.data.reserve(area);
  depth_.rect = framebuffer;
  depth_.data.assign(area, kDepthMax);
  stencil_.rect = framebuffer;
  stencil_.data.assign(area, std::uint8_t{0});
  state_ = initialRenderState(width, height);
  counters_ = {};
  for (DrawRecording& recording : recordings_)
    recording.clear();
  nextRecording_ = 0;
}

std::size_t bestDeviceToReshape(std::span<const CpuDevice* const> devices, int width, int height) {
  const auto needed = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const auto better = [needed](const CpuDevice* a, const CpuDevice* b) {
    const std::size_t ca = a->pixelCapacity(), cb = b->pixelCapacity();
    const bool aFits = ca >= needed, bFits = cb >= needed;
    if (aFits != bFits)
      return aFits;
    return aFits ? ca < cb : ca > cb;
  };
  return static_cast<std::size_t>(std::min_element(devices.begin(), devices.end(), better) -
                                  devices.begin());
}

void CpuDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  if (!state_.depthWrite)
    return;  // GL's depth mask applies to clears as well
  const std::uint32_t q = quantizeDepth(depth);
  depth_.fill(state_.scissor, q);
}

void CpuDevice::clearStencil(std::uint8_t value) {
  // GL applies the stencil write mask to clears as well.
  const std::uint8_t writeMask = state_.stencilWriteMask;
  if (writeMask == 0xFF)
    return stencil_.fill(state_.scissor, value);
  const PixelRect& r = state_.scissor;
  if (r.empty())
    return;
  for (int y = r.y0; y < r.y1; ++y) {
    std::uint8_t* row = &stencil_.at(r.x0, y);
    for (int i = 0; i < r.width(); ++i)
      row[i] = writeThroughMask(row[i], value, writeMask);
  }
}

void CpuDevice::drawTriangles(std::span<const WindowVertex> vertices,
                              std::span<const std::uint32_t> indices) {
  rasterize(vertices, indices, nullptr);
}

void CpuDevice::rasterize(std::span<const WindowVertex> vertices,
                          std::span<const std::uint32_t> indices, DrawRecording* recording) {
  // The draw is validated as a whole before any pixel changes, so an error leaves the
  // buffers untouched.
  checkDraw(vertices, indices);
  FragmentWriter writer(state_, depth_, stencil_);
  if (recording) {
    RecordingWriter recorder(writer, *recording);
    raster::drawTriangles(state_, vertices, indices, recorder, &counters_);
  } else {
    raster::drawTriangles(state_, vertices, indices, writer, &counters_);
  }
  counters_.fragments += writer.fragments;
}

void CpuDevice::drawMesh(const TriangleSource& source) {
  const std::uint64_t key = source.contentKey();
  for (const DrawRecording& recording : recordings_)
    if (recording.serves(key, state_.scissor))
      return replay(recording);
  const TriangleDraw draw = trianglesToDraw(source, state_.scissor);
  // Only a draw that culls nothing holds every triangle a later draw may need.
  if (key == 0 || state_.cull != CullMode::None)
    return rasterize(draw.vertices, draw.indices, nullptr);
  DrawRecording& recording = recordings_[nextRecording_];
  nextRecording_ = (nextRecording_ + 1) % recordings_.size();
  // A draw that is refused leaves the recording unfinished, so it serves nothing.
  recording.start(key, state_.scissor);
  rasterize(draw.vertices, draw.indices, &recording);
  recording.finish();
}

void CpuDevice::replay(const DrawRecording& recording) {
  // The recorded blocks lie inside the recorded scissor; only those inside the current one are
  // this draw's (the same pixels a fresh traversal of the smaller rectangle would visit).
  const PixelRect& scissor = state_.scissor;
  FragmentWriter writer(state_, depth_, stencil_);
  const std::vector<DrawRecording::Triangle>& triangles = recording.triangles();
  const std::vector<DrawRecording::Block>& blocks = recording.blocks();
  counters_.trianglesReplayed += triangles.size();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const DrawRecording::Triangle& triangle = triangles[t];
    if (state_.culls(triangle.frontFacing)) {
      ++counters_.trianglesCulled;
      continue;
    }
    writer.begin(triangle.plane, triangle.frontFacing);
    const std::size_t end = t + 1 < triangles.size() ? triangles[t + 1].firstBlock : blocks.size();
    for (std::size_t k = triangle.firstBlock; k < end; ++k) {
      const DrawRecording::Block& block = blocks[k];
      const std::uint64_t mask = block.mask & blockMaskInside(block.x, block.y, scissor);
      if (mask != 0)
        writer.coveredBlock(block.x, block.y, mask);
    }
  }
  counters_.fragments += writer.fragments;
}

std::vector<std::uint8_t> CpuDevice::readStencil(const PixelRect& rect) const {
  return stencil_.copy(rect);
}

std::vector<std::uint32_t> CpuDevice::readDepth(const PixelRect& rect) const {
  return depth_.copy(rect);
}

}  // namespace recode::raster
