// posed_vertex_box.hpp. The SIMD part is compiled once per Highway target (foreach_target.h
// re-includes this file) and chosen at run time. It transforms the vertices with the scalar
// code's operations in the scalar code's order, one IEEE multiply or add at a time (this file
// is built with -ffp-contract=off: a fused multiply-add would round differently), so every
// lane holds exactly the coordinate the scalar loop computes. The minimum and maximum of a set
// of such values are then the same bits whichever order they are compared in, unless the
// extreme is a zero (+0 and -0 compare equal) or a NaN is among them: those boxes are made
// again by the scalar loop.
#include "posed_vertex_box.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#if RECODE_SIM_HWY
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "posed_vertex_box.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace recode::core::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Over the first count - count % lanes vertices (xyz interleaved): the smallest and largest
// world coordinate per axis, and whether any was NaN. Returns how many vertices it covered.
// linear: row by row (raster::Pose's layout); translation: three.
std::size_t PosedVertexBoxLanes(const double* xyz, std::size_t count, const double* linear,
                                const double* translation, double* lo, double* hi, bool* sawNaN) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  using V = hn::Vec<decltype(d)>;
  std::array<V, 3> min, max;
  for (int k = 0; k < 3; ++k) {
    min[static_cast<std::size_t>(k)] = hn::Set(d, std::numeric_limits<double>::infinity());
    max[static_cast<std::size_t>(k)] = hn::Set(d, -std::numeric_limits<double>::infinity());
  }
  auto nan = hn::Zero(d);  // lanes that ever held a NaN: all bits set there
  std::size_t i = 0;
  for (; i + lanes <= count; i += lanes) {
    V x, y, z;
    hn::LoadInterleaved3(d, xyz + 3 * i, x, y, z);
    for (std::size_t k = 0; k < 3; ++k) {
      // posedPoint's order: the x and y rows ((l0 x + l1 y) + l2 z) + t, the z row
      // (l0 x + (l1 y + l2 z)) + t.
      const V c0 = hn::Mul(hn::Set(d, linear[3 * k]), x);
      const V c1 = hn::Mul(hn::Set(d, linear[3 * k + 1]), y);
      const V c2 = hn::Mul(hn::Set(d, linear[3 * k + 2]), z);
      const V sum = k < 2 ? hn::Add(hn::Add(c0, c1), c2) : hn::Add(c0, hn::Add(c1, c2));
      const V w = hn::Add(sum, hn::Set(d, translation[k]));
      min[k] = hn::Min(min[k], w);
      max[k] = hn::Max(max[k], w);
      nan = hn::Or(nan, hn::VecFromMask(d, hn::IsNaN(w)));
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    lo[k] = hn::GetLane(hn::MinOfLanes(d, min[k]));
    hi[k] = hn::GetLane(hn::MaxOfLanes(d, max[k]));
  }
  const hn::RebindToUnsigned<decltype(d)> du;
  *sawNaN = !hn::AllFalse(du, hn::Ne(hn::BitCast(du, nan), hn::Zero(du)));
  return i;
}

}  // namespace HWY_NAMESPACE
}  // namespace recode::core::detail
HWY_AFTER_NAMESPACE();
#endif  // RECODE_SIM_HWY

#if !defined(HWY_ONCE) || HWY_ONCE
namespace recode::core::detail {

#if RECODE_SIM_HWY
HWY_EXPORT(PosedVertexBoxLanes);
#endif

namespace {

// A coordinate whose bits the order of the comparisons could decide.
bool orderMatters(double extreme) {
  return extreme == 0.0 || std::isnan(extreme);
}

}  // namespace

Aabb posedVertexBoxScalar(std::span<const Eigen::Vector3d> local, const Eigen::Matrix3d& linear,
                          const Eigen::Vector3d& translation) {
  Aabb box;
  const raster::Pose pose = rasterPose(linear, translation);
  for (const Eigen::Vector3d& v : local)
    box.extend(posedPoint(pose, v));
  return box;
}

Aabb posedVertexBox(std::span<const Eigen::Vector3d> local, const Eigen::Matrix3d& linear,
                    const Eigen::Vector3d& translation) {
#if RECODE_SIM_HWY
  if (local.empty())
    return Aabb{};  // (and no vertex to take the address of)
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "vertices must be packed xyz");
  const raster::Pose pose = rasterPose(linear, translation);
  Aabb box;
  bool sawNaN = false;
  const std::size_t done = HWY_DYNAMIC_DISPATCH(PosedVertexBoxLanes)(
      local.data()->data(), local.size(), pose.linear.data(), pose.translation.data(),
      box.min.data(), box.max.data(), &sawNaN);
  box.extend(posedVertexBoxScalar(local.subspan(done), linear, translation));
  bool redo = sawNaN;
  for (int k = 0; k < 3; ++k)
    redo = redo || orderMatters(box.min[k]) || orderMatters(box.max[k]);
  if (!redo)
    return box;
#endif
  return posedVertexBoxScalar(local, linear, translation);
}

}  // namespace recode::core::detail
#endif  // HWY_ONCE
