// The skip-apart mode's test: fragment slacks from the frame, then GJK on the vertex hulls with
// the slacks as a margin (docs/algorithm.md section 11 derives each bound).
#include "recode/refine/proven_apart.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "recode/geometry/convex_distance.hpp"
#include "recode/raster/state.hpp"

namespace recode::core {

namespace {

// One step of the 24-bit depth buffer, in normalised depth.
constexpr double kDepthStep = 1.0 / static_cast<double>(raster::kDepthMax);

// Whether every vertex of a block with world box `box` maps into the device's range in `view`:
// the mapping is monotone along each axis, so the box's corners bound every vertex.
bool mappable(const OrthoView& view, const Aabb& box) {
  try {
    static_cast<void>(view.toWindow(box.min));
    static_cast<void>(view.toWindow(box.max));
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

Eigen::Vector3d fragmentSlack(const OrthoView& view, const Aabb& box) {
  const Eigen::Vector3d extent = view.toPlane(box.max) - view.toPlane(box.min);
  // The block's extent across the view in 1/256 pixels, one pixel added for the snapping: no
  // edge of a triangle, and no sample inside it from its first vertex, is longer.
  const double pixels = std::max(std::fabs(extent.x()) / view.pixelWidth(),
                                 std::fabs(extent.y()) / view.pixelHeight());
  const double fixedExtent = 256.0 * (pixels + 1.0);
  // The plane's rounding is at most 26 u E^2 + 2 u with u = 2^-53 (a slope is at most 2E over
  // an integer area of at least 1, times an offset of at most E); 2^-47 E^2 is over twice that.
  const double planeRounding = std::ldexp(fixedExtent * fixedExtent, -47);
  // Half a step for the vertex depth's float rounding and half for the quantisation, doubled.
  const double depth = (2.0 * kDepthStep + planeRounding) * (view.depthMax() - view.depthMin());
  // Snapping moves a vertex at most 1/512 pixel along x and y; doubled.
  const Eigen::Vector3d plane(view.pixelWidth() / 256.0, view.pixelHeight() / 256.0, depth);
  return view.fromPlane(plane).cwiseAbs();
}

namespace {

// Whether both blocks' fragments can be bounded in `frame`'s view: a view the frame and the
// pair's depth range make, and every vertex inside its range. Then the sum of the two blocks'
// fragment slacks in it.
std::optional<Eigen::Vector3d> pairSlack(const Aabb& a, const Aabb& b, const FrameSpec& frame) {
  const auto [depthMin, depthMax] = pairDepthRange(frame.axis, a, b);
  std::optional<OrthoView> view;
  try {
    view.emplace(frame.axis, frame.window, frame.width, frame.height, depthMin, depthMax);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a frame or depth range the view refuses: collidePair refuses it
  }
  if (!mappable(*view, a) || !mappable(*view, b))
    return std::nullopt;
  return fragmentSlack(*view, a) + fragmentSlack(*view, b);
}

bool drawableLocally(const PosedBlock& block) {
  if (!std::isfinite(block.localExtent) || !block.pose.matrix().allFinite())
    return false;
  const double rows = block.pose.linear().cwiseAbs().rowwise().sum().maxCoeff();
  return rows * block.localExtent + block.pose.translation().cwiseAbs().maxCoeff() < 1e300;
}

}  // namespace

bool provenApart(const PairBlock& a, const PairBlock& b, const FrameSpec& frame) {
  if (!a.drawable() || !b.drawable() || a.mesh().vertices.empty() || b.mesh().vertices.empty())
    return false;
  const std::optional<Eigen::Vector3d> margin = pairSlack(a.box(), b.box(), frame);
  return margin && hullsApartBeyond(a.mesh().vertices, b.mesh().vertices, *margin);
}

bool provenApart(const PosedBlock& a, const PosedBlock& b, const FrameSpec& frame) {
  if (!drawableLocally(a) || !drawableLocally(b))
    return false;
  const std::optional<Eigen::Vector3d> margin = pairSlack(a.worldBox, b.worldBox, frame);
  return margin && hullsApartBeyond(PosedPoints{a.local.vertices, a.pose},
                                    PosedPoints{b.local.vertices, b.pose}, *margin);
}

PairResult skippedResult(const Aabb& a, const Aabb& b, const FrameSpec& frame) {
  PairResult r;
  const auto [depthMin, depthMax] = pairDepthRange(frame.axis, a, b);
  r.depthMin = depthMin;
  r.depthMax = depthMax;
  return r;
}

PairResult skippedResult(const PairBlock& a, const PairBlock& b, const FrameSpec& frame) {
  return skippedResult(a.box(), b.box(), frame);
}

}  // namespace recode::core
