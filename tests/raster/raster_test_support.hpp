#pragma once
// Small helpers shared by the raster suites.

#include <cstdint>
#include <vector>

#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::test {

// Puts the device in "count every fragment" mode: no depth test or write, stencil +1 per
// fragment of either facing.
inline void setCountingState(raster::DepthStencilDevice& dev) {
  using namespace raster;
  dev.setDepthFunc(CompareFunc::Always);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
}

inline std::vector<raster::Command> countingCommands() {
  using namespace raster;
  return {cmd::DepthFunc{CompareFunc::Always}, cmd::DepthWriteMask{false},
          cmd::StencilFunc{CompareFunc::Always, 0, 0xFF},
          cmd::StencilOpsCmd{Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap}}};
}

// Draws a single triangle.
inline void drawTriangle(raster::DepthStencilDevice& dev, raster::WindowVertex a,
                         raster::WindowVertex b, raster::WindowVertex c) {
  const raster::WindowVertex v[3] = {a, b, c};
  const std::uint32_t i[3] = {0, 1, 2};
  dev.drawTriangles(v, i);
}

}  // namespace recode::test
