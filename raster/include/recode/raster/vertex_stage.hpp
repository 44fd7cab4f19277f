#pragma once
// The vertex stage (docs/rasterization.md, section 2.1): a block's object-space vertex to the
// window vertex a draw receives. Object to world by the block's pose, world to window by the
// view's mapping, then x and y snapped to the 1/256-pixel grid and z rounded to float. Every
// step is one IEEE-754 double operation, in the order written here, none fused and none
// reordered. The CPU reference makes its world vertices (core::posedPoint) and its window
// vertices (core::OrthoView::toWindow) with these functions, and a device that runs the stage
// itself (a posed draw: TriangleSource::posedMesh) must give the same bits.
//
// Inline: callers must be compiled without floating-point contraction (-ffp-contract=off, as
// the project's libraries are) for a multiply and an add to stay two roundings.

#include <array>
#include <cmath>
#include <cstddef>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/window_vertex.hpp"

namespace recode::raster {

// Object to world: world = linear · p + translation, `linear` row by row.
struct Pose {
  std::array<double, 9> linear{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  std::array<double, 3> translation{0.0, 0.0, 0.0};
};

// World to window for an orthographic view along a world axis (docs/algorithm.md, section 2).
struct WindowMapping {
  // The world coordinates that become the image plane's u and v and the view axis d, in that
  // order: along Z (0, 1, 2), along X (1, 2, 0), along Y (2, 0, 1).
  std::array<int, 3> axes{0, 1, 2};
  double umin = 0.0;
  double urange = 1.0;  // umax - umin, as one subtraction
  double width = 1.0;   // pixels
  double vmin = 0.0;
  double vrange = 1.0;  // vmax - vmin
  double height = 1.0;
  double depthMax = 1.0;    // the near end of the depth range (window depth 0)
  double depthRange = 1.0;  // depthMax - depthMin
};

// The whole stage's parameters for one draw of a block.
struct VertexTransform {
  Pose pose;
  WindowMapping window;
};

// linear · p + translation. Rows x and y as ((l0 p0 + l1 p1) + l2 p2) + t, row z as
// (l0 p0 + (l1 p1 + l2 p2)) + t: the order Eigen's Matrix3d * Vector3d took in the x86-64 build
// every golden result was made with, written out so that no build or vectorisation changes it.
[[nodiscard]] inline std::array<double, 3> poseVertex(const Pose& pose,
                                                      const std::array<double, 3>& p) {
  const std::array<double, 9>& l = pose.linear;
  const double x = (l[0] * p[0] + l[1] * p[1]) + l[2] * p[2];
  const double y = (l[3] * p[0] + l[4] * p[1]) + l[5] * p[2];
  const double z = l[6] * p[0] + (l[7] * p[1] + l[8] * p[2]);
  return {x + pose.translation[0], y + pose.translation[1], z + pose.translation[2]};
}

// A world point's window position before snapping: x = (w[u] - umin) / urange · width,
// y = (w[v] - vmin) / vrange · height, z = (depthMax - w[d]) / depthRange.
struct WindowPosition {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

[[nodiscard]] inline WindowPosition mapToWindow(const WindowMapping& m,
                                                const std::array<double, 3>& world) {
  const double u = world[static_cast<std::size_t>(m.axes[0])];
  const double v = world[static_cast<std::size_t>(m.axes[1])];
  const double d = world[static_cast<std::size_t>(m.axes[2])];
  return {(u - m.umin) / m.urange * m.width, (v - m.vmin) / m.vrange * m.height,
          (m.depthMax - d) / m.depthRange};
}

// Whether a draw can take the position: |x|, |y| <= kMaxWindowCoordinate and 0 <= z <= 1
// (false for a NaN), section 2's rule for a referenced vertex.
[[nodiscard]] inline bool drawablePosition(const WindowPosition& p) {
  const double limit = static_cast<double>(kMaxWindowCoordinate);
  return std::fabs(p.x) <= limit && std::fabs(p.y) <= limit && p.z >= 0.0 && p.z <= 1.0;
}

// x and y to the 1/256-pixel grid (snapToSubpixel: exact in float), z rounded to the nearest
// float, ties to even.
[[nodiscard]] inline WindowVertex snapPosition(const WindowPosition& p) {
  return {snapToSubpixel(p.x), snapToSubpixel(p.y), static_cast<float>(p.z)};
}

// The stage for one object-space vertex: snapPosition(mapToWindow(poseVertex)). A posed draw
// draws only blocks whose every vertex is a drawablePosition.
[[nodiscard]] inline WindowVertex vertexStage(const VertexTransform& t,
                                              const std::array<double, 3>& local) {
  return snapPosition(mapToWindow(t.window, poseVertex(t.pose, local)));
}

}  // namespace recode::raster
