#pragma once
// The vertex a draw receives (docs/rasterization.md, section 2).

namespace recode::raster {

// A vertex in GL window coordinates: x right, y up, pixel (i, j) has its centre at
// (i + 0.5, j + 0.5), depth z in [0, 1]. x and y are expected on the 1/256-pixel grid
// (see snapToSubpixel); a device snaps them to that grid itself with round-half-to-even.
struct WindowVertex {
  float x = 0.0f;  // pixels from the left edge
  float y = 0.0f;  // pixels from the bottom edge
  float z = 0.0f;  // depth, 0 nearest and 1 farthest
};

}  // namespace recode::raster
