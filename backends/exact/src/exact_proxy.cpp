#include "recode/backends/exact_proxy.hpp"

#include "recode/raster/device_checks.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::backends {

std::vector<ProxyTriangle> buildProxyTriangles(std::span<const raster::WindowVertex> vertices,
                                               std::span<const std::uint32_t> indices,
                                               const raster::RenderState& state) {
  raster::checkDraw(vertices, indices);
  std::vector<ProxyTriangle> proxies;
  proxies.reserve(indices.size() / 3);
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    const raster::FixedVertex v[3] = {raster::snapVertex(vertices[indices[k]]),
                                      raster::snapVertex(vertices[indices[k + 1]]),
                                      raster::snapVertex(vertices[indices[k + 2]])};
    const auto setup = raster::setupTriangle(v[0], v[1], v[2]);
    if (!setup || state.culls(setup->frontFacing))
      continue;
    const raster::PixelRect rect = setup->bounds.intersect(state.scissor);
    if (rect.empty())
      continue;
    ProxyTriangle p{};
    p.pixelRect[0] = rect.x0;
    p.pixelRect[1] = rect.y0;
    p.pixelRect[2] = rect.x1;
    p.pixelRect[3] = rect.y1;
    for (int i = 0; i < 3; ++i) {
      // checkDraw bounds |x|, |y| by 32768 pixels, so the fixed-point values fit 24 bits.
      std::int32_t* xy = i < 2 ? &p.fixedV0V1[2 * i] : p.fixedV2;
      xy[0] = static_cast<std::int32_t>(v[i].x);
      xy[1] = static_cast<std::int32_t>(v[i].y);
      p.z[i] = v[i].z;
    }
    p.frontFacing = setup->frontFacing ? 1 : 0;
    proxies.push_back(p);
  }
  return proxies;
}

}  // namespace recode::backends
