#include "recode/raster/cpu_device.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "recode/raster/block_fragments.hpp"
#include "recode/raster/device_checks.hpp"
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
      : state_(state), depth_(depth), stencil_(stencil) {}

  void beginTriangle(const TriangleSetup& triangle,
                     const std::array<FixedVertex, 3>& /*snapped*/) override {
    plane_ = &triangle.depth;
    ops_ = &state_.opsFor(triangle.frontFacing);
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
    fragments += static_cast<std::uint64_t>(applyBlockFragments(block, mask));
  }

  std::uint64_t fragments = 0;

 private:
  const RenderState& state_;
  PixelBuffer<std::uint32_t>& depth_;
  PixelBuffer<std::uint8_t>& stencil_;
  const DepthPlane* plane_ = nullptr;
  const StencilOps* ops_ = nullptr;
};

}  // namespace

CpuDevice::CpuDevice(int width, int height) {
  checkFramebufferSize(width, height);
  const PixelRect framebuffer{0, 0, width, height};
  depth_ = PixelBuffer<std::uint32_t>(framebuffer, kDepthMax);
  stencil_ = PixelBuffer<std::uint8_t>(framebuffer, std::uint8_t{0});
  state_ = initialRenderState(width, height);
}

void CpuDevice::setScissor(const PixelRect& rect) {
  state_.setScissor(rect, width(), height());
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
  const PixelRect& r = state_.scissor;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = stencil_.at(x, y);
      s = writeThroughMask(s, value, state_.stencilWriteMask);
    }
  }
}

void CpuDevice::setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) {
  state_.stencilFunc = func;
  state_.stencilRef = ref;
  state_.stencilValueMask = valueMask;
}

void CpuDevice::setStencilOps(Face face, const StencilOps& ops) {
  state_.setStencilOps(face, ops);
}

void CpuDevice::drawTriangles(std::span<const WindowVertex> vertices,
                              std::span<const std::uint32_t> indices) {
  // The draw is validated as a whole before any pixel changes, so an error leaves the
  // buffers untouched.
  checkDraw(vertices, indices);
  FragmentWriter writer(state_, depth_, stencil_);
  raster::drawTriangles(state_, vertices, indices, writer, &counters_);
  counters_.fragments += writer.fragments;
}

void CpuDevice::drawMesh(const TriangleSource& source) {
  // Triangles that cover no pixel centre in the scissor write nothing, so leaving them out
  // changes no bit; a source that cannot tell (or whose full draw would be refused) is drawn
  // whole, so its refusal is the full draw's.
  const std::optional<TriangleDraw> near = source.trianglesMeeting(state_.scissor);
  if (!near) {
    const TriangleDraw all = source.allTriangles();
    return drawTriangles(all.vertices, all.indices);
  }
  drawTriangles(near->vertices, near->indices);
}

std::vector<std::uint8_t> CpuDevice::readStencil(const PixelRect& rect) const {
  return stencil_.copy(rect);
}

std::vector<std::uint32_t> CpuDevice::readDepth(const PixelRect& rect) const {
  return depth_.copy(rect);
}

}  // namespace recode::raster
