#include "recode/raster/cpu_device.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster {

namespace {

// Writes the fragments of one triangle into the buffers.
class FragmentWriter final : public BlockSink {
 public:
  FragmentWriter(const TriangleSetup& tri, const DepthStencilState& state, int stride,
                 std::uint32_t* depth, std::uint8_t* stencil)
      : tri_(tri),
        state_(state),
        ops_(tri.frontFacing ? state.frontOps : state.backOps),
        stride_(static_cast<std::size_t>(stride)),
        depth_(depth),
        stencil_(stencil) {}

  void coveredBlock(int blockX, int blockY, std::uint64_t mask) override {
    // The contract's z = (z0 + tx) + ty with tx depending only on the column and ty only on
    // the row: precomputing both per block gives the same roundings, so the same bits.
    const DepthPlane& p = tri_.depth;
    double zx[kBlockSize], ty[kBlockSize];
    for (int k = 0; k < kBlockSize; ++k) {
      zx[k] = p.z0 + p.dzdx * static_cast<double>(pixelCentreFixed(blockX + k) - p.x0);
      ty[k] = p.dzdy * static_cast<double>(pixelCentreFixed(blockY + k) - p.y0);
    }
    while (mask != 0) {
      const int bit = __builtin_ctzll(mask);
      mask &= mask - 1;
      const int col = bit & (kBlockSize - 1), row = bit / kBlockSize;
      const std::uint32_t z = quantizeDepth(zx[col] + ty[row]);
      const std::size_t i =
          static_cast<std::size_t>(blockY + row) * stride_ + static_cast<std::size_t>(blockX + col);
      applyFragment(state_, ops_, z, depth_[i], stencil_[i]);
      ++fragments;
    }
  }

  std::uint64_t fragments = 0;

 private:
  const TriangleSetup& tri_;
  const DepthStencilState& state_;
  const StencilOps& ops_;
  std::size_t stride_;
  std::uint32_t* depth_;
  std::uint8_t* stencil_;
};

}  // namespace

CpuDevice::CpuDevice(int width, int height) : width_(width), height_(height) {
  checkFramebufferSize(width, height);
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  depth_.assign(n, kDepthMax);
  stencil_.assign(n, 0);
  scissor_ = framebufferRect();
}

void CpuDevice::setScissor(const PixelRect& rect) {
  scissor_ = rect.intersect(framebufferRect());
}

void CpuDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  if (!state_.depthWrite)
    return;  // GL's depth mask applies to clears as well
  const std::uint32_t q = quantizeDepth(depth);
  for (int y = scissor_.y0; y < scissor_.y1; ++y) {
    std::fill(depth_.begin() + static_cast<std::ptrdiff_t>(index(scissor_.x0, y)),
              depth_.begin() + static_cast<std::ptrdiff_t>(index(scissor_.x1, y)), q);
  }
}

void CpuDevice::clearStencil(std::uint8_t value) {
  // GL applies the stencil write mask to clears as well.
  const std::uint8_t wm = state_.stencilWriteMask;
  for (int y = scissor_.y0; y < scissor_.y1; ++y) {
    for (int x = scissor_.x0; x < scissor_.x1; ++x) {
      std::uint8_t& s = stencil_[index(x, y)];
      s = static_cast<std::uint8_t>((value & wm) | (s & static_cast<std::uint8_t>(~wm)));
    }
  }
}

void CpuDevice::setStencilFunc(CompareFunc func, std::uint8_t ref, std::uint8_t valueMask) {
  state_.stencilFunc = func;
  state_.stencilRef = ref;
  state_.stencilValueMask = valueMask;
}

void CpuDevice::setStencilOps(Face face, const StencilOps& ops) {
  if (face != Face::Back)
    state_.frontOps = ops;
  if (face != Face::Front)
    state_.backOps = ops;
}

void CpuDevice::drawTriangles(std::span<const WindowVertex> vertices,
                              std::span<const std::uint32_t> indices) {
  checkDraw(vertices, indices);
  // The draw is validated as a whole before any pixel changes, so an error leaves the
  // buffers untouched.
  for (std::size_t k = 0; k < indices.size(); k += 3) {
    ++counters_.trianglesSubmitted;
    const auto tri =
        setupTriangle(snapVertex(vertices[indices[k]]), snapVertex(vertices[indices[k + 1]]),
                      snapVertex(vertices[indices[k + 2]]));
    if (!tri) {
      ++counters_.trianglesDegenerate;
      continue;
    }
    if ((state_.cull == CullMode::Front && tri->frontFacing) ||
        (state_.cull == CullMode::Back && !tri->frontFacing)) {
      ++counters_.trianglesCulled;
      continue;
    }
    FragmentWriter writer(*tri, state_, width_, depth_.data(), stencil_.data());
    traverseTriangle(*tri, scissor_, writer, &counters_.traversal);
    counters_.fragments += writer.fragments;
  }
}

std::vector<std::uint8_t> CpuDevice::readStencil(const PixelRect& rect) const {
  return copyRect(stencil_, rect);
}

std::vector<std::uint32_t> CpuDevice::readDepth(const PixelRect& rect) const {
  return copyRect(depth_, rect);
}

}  // namespace recode::raster
