#pragma once
// What the compute device's test files share: the state under which every fragment of a draw
// shows in the stencil, and the comparison of a device's buffers with the CPU device's.

#include <catch2/catch.hpp>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/device.hpp"

namespace recode::test {

// LEQUAL with depth writes, and a stencil that counts front fragments that pass and inverts on
// back ones that fail: every fragment's order shows.
inline void countingState(raster::DepthStencilDevice& device) {
  device.setDepthFunc(raster::CompareFunc::LEqual);
  device.setStencilFunc(raster::CompareFunc::Always, 0, 0xFF);
  device.setStencilOps(raster::Face::Front, {raster::StencilOp::Keep, raster::StencilOp::Invert,
                                             raster::StencilOp::IncrWrap});
  device.setStencilOps(raster::Face::Back, {raster::StencilOp::Keep, raster::StencilOp::Invert,
                                            raster::StencilOp::DecrWrap});
}

// `device` holds `reference`'s depth and stencil over the whole framebuffer.
inline void expectSameBuffers(const raster::DepthStencilDevice& device,
                              const raster::CpuDevice& reference) {
  const raster::PixelRect all{0, 0, reference.width(), reference.height()};
  CHECK(device.readDepth(all) == reference.readDepth(all));
  CHECK(device.readStencil(all) == reference.readStencil(all));
}

}  // namespace recode::test
