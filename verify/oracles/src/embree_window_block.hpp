#pragma once
// A block in window space as the Embree oracle sees it: the same snapped x and y the device
// draws (24.8 fixed point), the depth of every vertex both unrounded (double, for the oracle's
// own depths) and as the device receives it (float, for Embree's ray casts). Exact predicates
// on it: which triangles cover a pixel centre, how near the centre is to a projected edge.
// Internal to the Embree oracle.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/state.hpp"

namespace recode::verify::detail {

struct WindowBlock {
  std::vector<std::int64_t> fx, fy;  // 24.8 fixed point (1/256 px units)
  std::vector<float> x, y, zf;       // window x, y (exactly fx / 256) and the device's depth
  std::vector<double> z;             // depth before rounding to float
  std::vector<core::Triangle> triangles;
  std::vector<std::int64_t> area2;  // twice the signed projected area, in the submitted order
  std::vector<std::array<std::uint32_t, 2>> edges;  // each projected edge once
};

// Maps a world block through `view` as core::collidePair does. Throws std::invalid_argument
// (naming `name`) for a triangle index out of range or a vertex the view cannot map.
[[nodiscard]] WindowBlock makeWindowBlock(const core::OrthoView& view,
                                          const core::TriangleMesh& mesh, const char* name);

// Fixed-point coordinate of pixel i's centre.
[[nodiscard]] constexpr std::int64_t centreFixed(int i) {
  return std::int64_t{i} * raster::kSubpixelOne + raster::kSubpixelOne / 2;
}

// Whether the closed projection of triangle t contains the point (fixed point).
[[nodiscard]] bool covers(const WindowBlock& block, std::size_t t, std::int64_t px,
                          std::int64_t py);

// Depth of triangle t's plane at the point; t must have a non-zero projected area.
[[nodiscard]] double depthAt(const WindowBlock& block, std::size_t t, std::int64_t px,
                             std::int64_t py);

// The nearest and farthest depth of every triangle whose closed projection contains the point
// (nullopt: none does). The slow, sure way, for pixels where a ray cast is in doubt.
[[nodiscard]] std::optional<std::array<double, 2>> bruteForceInterval(const WindowBlock& block,
                                                                      std::int64_t px,
                                                                      std::int64_t py);

// Whether the point lies within 1/256 px (one fixed-point unit) of a projected edge.
[[nodiscard]] bool nearProjectedEdge(const WindowBlock& block, std::int64_t px, std::int64_t py);

// Pixels of a width x height frame whose centres lie in the closed box of the block's
// projected vertices.
[[nodiscard]] raster::PixelRect footprint(const WindowBlock& block, int width, int height);

// The contract's depth quantisation (docs/rasterization.md section 5), written out again here
// so the oracle does not lean on the device's code: clamp to [0, 1], round(z * (2^24 - 1))
// half to even.
[[nodiscard]] std::uint32_t quantiseDepth(double z);

}  // namespace recode::verify::detail
