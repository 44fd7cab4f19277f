// The frame of a block pair: an axis (given, or across the overlap's thinnest side), a pixel
// size (given, or from the resolution over the overlap), then the frame `recode run` uses.
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "recode/api/collision.hpp"
#include "recode/raster/state.hpp"

namespace recode {

namespace {

int axisIndex(core::ViewAxis axis) {
  return axis == core::ViewAxis::X ? 0 : axis == core::ViewAxis::Y ? 1 : 2;
}

// Ties go to z, then x, then y: z is the scenes' usual axis.
core::ViewAxis thinnestAxis(const core::Aabb& box) {
  const Eigen::Vector3d e = box.extent();
  core::ViewAxis best = core::ViewAxis::Z;
  for (const core::ViewAxis axis : {core::ViewAxis::X, core::ViewAxis::Y})
    if (e[axisIndex(axis)] < e[axisIndex(best)])
      best = axis;
  return best;
}

// The longer side of the box on the image plane of `axis`.
double longerPlaneSide(core::ViewAxis axis, const core::Aabb& box) {
  const Eigen::Vector3d e = box.extent();
  double side = 0.0;
  for (int k = 0; k < 3; ++k)
    if (k != axisIndex(axis))
      side = std::max(side, e[k]);
  return side;
}

core::ViewAxis axisOf(AxisChoice choice, const core::Aabb& overlap) {
  switch (choice) {
    case AxisChoice::X:
      return core::ViewAxis::X;
    case AxisChoice::Y:
      return core::ViewAxis::Y;
    case AxisChoice::Z:
      return core::ViewAxis::Z;
    case AxisChoice::Auto:
      break;
  }
  return overlap.isEmpty() ? core::ViewAxis::Z : thinnestAxis(overlap);
}

}  // namespace

core::FrameSpec chooseFrame(const core::Aabb& a, const core::Aabb& b,
                            const CollisionRequest& request) {
  core::Aabb overlap;
  overlap.min = a.min.cwiseMax(b.min);
  overlap.max = a.max.cwiseMin(b.max);
  const core::ViewAxis axis = axisOf(request.axis, overlap);
  if (request.pixelSize)
    return core::granularPairFrame(axis, *request.pixelSize, a, b);
  if (request.resolution < 1 || request.resolution > raster::kMaxFramebufferSize) {
    std::ostringstream m;
    m << "resolution " << request.resolution << " is outside 1.." << raster::kMaxFramebufferSize;
    throw std::invalid_argument(m.str());
  }
  core::Aabb both = a;
  both.extend(b);
  const double bothSide = longerPlaneSide(axis, both);
  double side = overlap.isEmpty() ? 0.0 : longerPlaneSide(axis, overlap);
  if (!(side > 0.0))
    side = bothSide;
  // Tips meeting make an overlap of almost nothing; its pixel would need a frame of millions of
  // pixels over the blocks. No finer than kMaxResolutionFrameSide pixels across both boxes.
  const double pixel = std::max(side / request.resolution, bothSide / kMaxResolutionFrameSide);
  return core::granularPairFrame(axis, pixel, a, b);
}

}  // namespace recode
