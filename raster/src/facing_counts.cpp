#include "recode/raster/facing_counts.hpp"

namespace recode::raster {

long long FacingCounts::unequalPixels() const {
  long long n = 0;
  for (std::size_t i = 0; i < front.size(); ++i)
    n += front[i] != back[i];
  return n;
}

FacingCounts countFacingFragments(DepthStencilDevice& device,
                                  std::span<const WindowVertex> vertices,
                                  std::span<const std::uint32_t> indices) {
  const PixelRect all{0, 0, device.width(), device.height()};
  device.setScissor(all);
  device.setDepthFunc(CompareFunc::Always);
  device.setDepthWriteMask(false);
  device.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  device.setStencilWriteMask(0xFF);
  device.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Incr});
  FacingCounts counts;
  device.clearStencil(0);
  device.setCullMode(CullMode::Back);
  device.drawTriangles(vertices, indices);
  counts.front = device.readStencil(all);
  device.clearStencil(0);
  device.setCullMode(CullMode::Front);
  device.drawTriangles(vertices, indices);
  counts.back = device.readStencil(all);
  return counts;
}

}  // namespace recode::raster
