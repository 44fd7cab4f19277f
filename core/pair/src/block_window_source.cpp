#include "block_window_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "recode/raster/device.hpp"

namespace recode::core::detail {

namespace {

using raster::PixelRect;
using raster::WindowVertex;

// Whether a window range [lo, hi] (pixels, before snapping) can hold, once snapped, the centre
// i + 0.5 of a pixel with first <= i < end. Snapping moves a coordinate by at most 1/512 pixel;
// the range is widened by 1/64.
bool holdsCentre(double lo, double hi, int first, int end) {
  constexpr double kSnapMargin = 1.0 / 64.0;
  const double i0 = std::max(std::ceil(lo - kSnapMargin - 0.5), static_cast<double>(first));
  const double i1 = std::min(std::floor(hi + kSnapMargin - 0.5), static_cast<double>(end - 1));
  return i0 <= i1;
}

// Whether a hierarchy box, moved by the pose, can hold a vertex of a triangle that covers a
// pixel centre of `rect`: the box's image-plane ranges, grown by a relative margin for the
// rounding of the world vertices (each made as linear * p + translation), mapped to the window
// by the view's own formula. That formula is monotonic, so a vertex inside the box maps inside
// the mapped range; a triangle covering a centre has that centre inside its vertices' box.
bool boxCanCover(const Aabb& local, const Eigen::Isometry3d& pose, bool identity,
                 const OrthoView& view, const PixelRect& rect) {
  Eigen::Vector3d centre = local.center(), half = 0.5 * local.extent();
  if (!identity) {
    const Eigen::Matrix3d linear = pose.linear();
    centre = linear * centre + pose.translation();
    half = linear.cwiseAbs() * half;
  }
  half += Eigen::Vector3d::Constant(1e-9 * (centre.cwiseAbs().maxCoeff() + half.maxCoeff()));
  const Eigen::Vector3d lo = view.toPlane(centre - half), hi = view.toPlane(centre + half);
  const ViewWindow& w = view.window();
  const auto toX = [&](double u) { return (u - w.umin) / (w.umax - w.umin) * view.width(); };
  const auto toY = [&](double v) { return (v - w.vmin) / (w.vmax - w.vmin) * view.height(); };
  return holdsCentre(toX(lo.x()), toX(hi.x()), rect.x0, rect.x1) &&
         holdsCentre(toY(lo.y()), toY(hi.y()), rect.y0, rect.y1);
}

// Whether the closed box of three window vertices holds the centre of a pixel of `rect`: the
// only triangles that can cover one. The coordinates are multiples of 1/256, so the
// differences are exact (as in pixelFootprint).
bool boxHoldsPixelCentre(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                         const PixelRect& rect) {
  const auto holds = [](float p, float q, float r, int lo, int hi) {
    const double mn = std::min({p, q, r}), mx = std::max({p, q, r});
    const double first = std::max(std::ceil(mn - 0.5), static_cast<double>(lo));
    const double last = std::min(std::floor(mx - 0.5), static_cast<double>(hi - 1));
    return first <= last;
  };
  return holds(a.x, b.x, c.x, rect.x0, rect.x1) && holds(a.y, b.y, c.y, rect.y0, rect.y1);
}

bool insideRange(const OrthoView& view, const Eigen::Vector3d& p, WindowVertex& out) {
  try {
    out = view.toWindow(p);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

BlockWindowSource::BlockWindowSource(const PairBlock& block, const OrthoView& view)
    : block_(block), view_(view) {
  culls_ = block.drawable() && block.hierarchy() != nullptr &&
           insideRange(view, block.box().min, corners_[0]) &&
           insideRange(view, block.box().max, corners_[1]);
  if (!culls_)
    (void)allTriangles();
}

std::span<const WindowVertex> BlockWindowSource::extremes() const {
  if (culls_)
    return corners_;
  return all_;
}

raster::TriangleDraw BlockWindowSource::allTriangles() const {
  if (!allMade_) {
    all_ = view_.toWindow(block_.mesh());
    allIndices_ = triangleIndices(block_.mesh());
    allMade_ = true;
  }
  return {all_, allIndices_};
}

std::optional<raster::TriangleDraw> BlockWindowSource::trianglesMeeting(
    const PixelRect& rect) const {
  if (!culls_)
    return std::nullopt;
  if (!nearRect_ || !(*nearRect_ == rect))
    gather(rect);
  return raster::TriangleDraw{near_, nearIndices_};
}

void BlockWindowSource::gather(const PixelRect& rect) const {
  nearRect_ = rect;
  candidates_.clear();
  near_.clear();
  nearIndices_.clear();
  if (rect.empty())
    return;
  const Eigen::Isometry3d& pose = block_.localToWorld();
  const bool identity = pose.matrix().isIdentity(0.0);
  block_.hierarchy()->collect(
      [&](const Aabb& box) { return boxCanCover(box, pose, identity, view_, rect); }, candidates_);
  const TriangleMesh& mesh = block_.mesh();
  for (const std::uint32_t t : candidates_) {
    const Triangle& tri = mesh.triangles[t];
    const WindowVertex a = view_.toWindow(mesh.vertices[tri[0]]);
    const WindowVertex b = view_.toWindow(mesh.vertices[tri[1]]);
    const WindowVertex c = view_.toWindow(mesh.vertices[tri[2]]);
    if (!boxHoldsPixelCentre(a, b, c, rect))
      continue;
    const auto first = static_cast<std::uint32_t>(near_.size());
    near_.insert(near_.end(), {a, b, c});
    nearIndices_.insert(nearIndices_.end(), {first, first + 1, first + 2});
  }
}

}  // namespace recode::core::detail
