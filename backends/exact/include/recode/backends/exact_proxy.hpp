#pragma once
// The CPU half of every exact GPU device (GL and Vulkan): a draw's triangles, validated,
// snapped and set up as the contract says, become proxy records, one per triangle that can
// touch a pixel, or one per band of 4 rows when the triangle's rectangle is tall and much larger
// than the triangle (a sliver's). The GPU draws each record as a rectangle over candidate pixels
// and decides coverage and depth itself in the fragment shader (shaders/exact_contract.glsl);
// the CPU only decides what needs no per-pixel work: facing, culling, zero area, and which
// columns of a band the triangle can reach.

#include <cstdint>
#include <span>
#include <vector>

#include "recode/raster/device.hpp"
#include "recode/raster/state.hpp"

namespace recode::backends {

// One triangle as the exact shaders read it: 14 tightly packed 32-bit fields, in this order, as
// per-instance vertex attributes.
struct ProxyTriangle {
  std::int32_t pixelRect[4];  // x0, y0, x1, y1: candidate pixels inside the scissor, half-open
  std::int32_t fixedV0V1[4];  // snapped X0, Y0, X1, Y1 (24.8 fixed point, |value| <= 2^23)
  std::int32_t fixedV2[2];    // snapped X2, Y2
  float z[3];                 // z0, z1, z2 as submitted, in submitted order
  std::int32_t frontFacing;   // 1 when the snapped area is positive, else 0
  // The depth plane's slopes dzdx, dzdy (per sub-pixel unit, anchored at the first submitted
  // vertex), set up on the CPU exactly as raster::setupTriangle sets them up: each double's
  // bits as two 32-bit words, low word first (GLSL's packDouble2x32).
  std::uint32_t slopeBits[4];
};
static_assert(sizeof(ProxyTriangle) == 72, "the shaders read 18 packed 32-bit fields");

// The proxies of one draw in index order, which is the order the GPU must draw them in (a
// triangle's bands are consecutive, bottom up, and share no pixel, so each pixel still meets the
// triangles in index order, each once). Throws std::invalid_argument exactly as CpuDevice does
// for an invalid draw (raster::checkDraw). Triangles of zero snapped area, culled by state.cull,
// or whose candidate pixels all lie outside state.scissor give no proxy.
[[nodiscard]] std::vector<ProxyTriangle> buildProxyTriangles(
    std::span<const raster::WindowVertex> vertices, std::span<const std::uint32_t> indices,
    const raster::RenderState& state);

// The same records into `proxies` (emptied first), keeping its memory: a caller that sets up
// draw after draw (ProxyCache) then allocates, and the system maps fresh pages, only for a draw
// larger than any before. After a refusal `proxies` is as it was.
void buildProxyTrianglesInto(std::span<const raster::WindowVertex> vertices,
                             std::span<const std::uint32_t> indices,
                             const raster::RenderState& state, std::vector<ProxyTriangle>& proxies);

}  // namespace recode::backends
