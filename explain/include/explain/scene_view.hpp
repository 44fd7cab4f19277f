#pragma once
// What the interactive page's 3-D view draws for one run (page/scene3d.js): both blocks as the
// reference's triangles in world coordinates, the frame (view axis, window, W x H), the depth
// range the passes map onto [0, 1] and the MOR, so that the picture and the buffers cannot
// disagree about where anything is.

#include <nlohmann/json.hpp>

#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"

namespace recode::explain {

// {"axis": "x"|"y"|"z", "window": [umin, vmin, umax, vmax], "resolution": [W, H],
//  "depth_range": [dmin, dmax], "mor": [x0, y0, x1, y1] or null,
//  "blocks": [{"name", "positions": [x, y, z, ...], "triangles": [i, j, k, ...]}, A then B]}.
// depth_range is core::pairDepthRange of the two blocks, the range the ray inspector's depths
// are over; positions are the meshes' vertices exactly as the pair ran on them.
[[nodiscard]] nlohmann::json sceneViewJson(const PairSetup& setup, const core::PairResult& result);

}  // namespace recode::explain
