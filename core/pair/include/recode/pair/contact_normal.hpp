#pragma once
// The contact normal and penetration depth of an overlap measured by the contact passes
// (docs/algorithm.md, "Contact normal and penetration depth"): the direction in which the
// sampled overlap solid is thinnest, turned to point from A towards B, and the overlap's
// extent along it.

#include <span>

#include <Eigen/Core>

namespace recode::core {

struct ContactNormal {
  // Unit vector, world space, pointing from A towards B: moving B along it separates the
  // blocks soonest (see contactNormal).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  // The overlap's width along `normal`, world units: every interfering pixel taken as its whole
  // square on the image plane, spanning its overlap interval along the view axis.
  double depth = 0.0;
};

// The overlap as the contact passes see it: both ends of every interfering pixel's overlap
// interval, at the pixel centre, in world space (near end then far end, pixel after pixel), and the
// half size of a pixel along the world axes (half the pixel width and height on the image plane's
// axes, 0 along the view axis).
struct OverlapSamples {
  std::span<const Eigen::Vector3d> ends;
  Eigen::Vector3d halfPixel = Eigen::Vector3d::Zero();
};

// Width of the sampled overlap along the unit direction d: the spread of the ends' projections
// plus one pixel square's extent along d.
[[nodiscard]] double overlapWidth(const OverlapSamples& samples, const Eigen::Vector3d& d);

// The unit direction of least overlapWidth (up to the search's resolution, about 0.01 degree),
// its sign not yet chosen. Searched from a fixed set of directions over the half sphere and the
// least-squares plane normals of the near and far ends, then refined locally. `samples.ends`
// must not be empty.
[[nodiscard]] Eigen::Vector3d thinnestDirection(const OverlapSamples& samples);

// The contact normal: thinnestDirection, signed from the blocks' vertices so that moving B along
// it separates the blocks after the shorter translation (max over A of x.n - min over B of x.n
// no greater than the same with A and B swapped; a tie keeps the sign whose largest component
// is positive), and the overlap width along it.
[[nodiscard]] ContactNormal contactNormal(const OverlapSamples& samples,
                                          std::span<const Eigen::Vector3d> verticesA,
                                          std::span<const Eigen::Vector3d> verticesB);

}  // namespace recode::core
