// The wrong readings of the vertex stage (vertex_stage_vectors.hpp): each one the contract's
// stage (raster/vertex_stage.hpp) with one step changed. Built, like the kit, without
// floating-point contraction: every product and sum written here is rounded on its own, and
// the fused reading calls std::fma.

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "recode/kit/vertex_stage_vectors.hpp"
#include "recode/raster/fixed_point.hpp"

namespace recode::kit {

namespace {

using raster::Pose;
using raster::WindowMapping;
using raster::WindowPosition;
using raster::WindowVertex;
using R = VertexStageReading;
using Vec3 = std::array<double, 3>;

constexpr std::array<VertexStageReadingInfo, 21> kWrong = {{
    {R::ZRowAsXY, "z_row_as_xy",
     "the z row summed as the x and y rows: ((l20 px + l21 py) + l22 pz) + tz"},
    {R::RowsRightFirst, "rows_right_first", "every row summed as (l0 p0 + (l1 p1 + l2 p2)) + t"},
    {R::TranslationFirst, "translation_first",
     "the translation added first: ((t + l0 p0) + l1 p1) + l2 p2"},
    {R::FmaPose, "fma_pose",
     "each row's products fused into its sums with std::fma, in the contract's order"},
    {R::FloatPose, "float_pose", "the pose in single precision"},
    {R::LinearTransposed, "linear_transposed", "the linear part read column by column"},
    {R::FloatWindow, "float_window", "the window mapping in single precision"},
    {R::WindowScaleFirst, "window_scale_first", "x as (w[u] - umin) * (width / urange), y alike"},
    {R::WindowMultiplyFirst, "window_multiply_first",
     "x as (w[u] - umin) * width / urange, y alike"},
    {R::DepthReciprocal, "depth_reciprocal", "z as (depthMax - w[d]) * (1 / depthRange)"},
    {R::DepthFromMin, "depth_from_min", "z as 1 - (w[d] - depthMin) / depthRange"},
    {R::DepthReversed, "depth_reversed",
     "z as (w[d] - depthMin) / depthRange: near and far swapped"},
    {R::AxesInverted, "axes_inverted", "the view's axes read as the inverse permutation"},
    {R::YDown, "y_down", "y as (vmax - w[v]) / vrange * height: rows from the top"},
    {R::SnapAfterFloat, "snap_after_float", "x and y rounded to float, then snapped"},
    {R::SnapHalfAway, "snap_half_away", "snap ties away from zero (std::round)"},
    {R::SnapHalfUp, "snap_half_up", "snap ties up: floor(x 256 + 0.5)"},
    {R::SnapThroughInteger, "snap_through_integer",
     "snapped through an integer: float(llrint(x 256)) / 256, -0 becomes +0"},
    {R::DepthTruncate, "depth_truncate", "z rounded to float toward zero"},
    {R::DepthTiesAway, "depth_ties_away", "z rounded to the nearest float, ties away from zero"},
    {R::DepthFlushSubnormal, "depth_flush_subnormal",
     "z rounded to the nearest float, a subnormal flushed to zero"},
}};

// ---- the pose -----------------------------------------------------------------------

Vec3 floatPose(const Pose& pose, const Vec3& p) {
  std::array<float, 9> l{};
  for (std::size_t i = 0; i < 9; ++i)
    l[i] = static_cast<float>(pose.linear[i]);
  const float x = static_cast<float>(p[0]);
  const float y = static_cast<float>(p[1]);
  const float z = static_cast<float>(p[2]);
  const float wx = (l[0] * x + l[1] * y) + l[2] * z;
  const float wy = (l[3] * x + l[4] * y) + l[5] * z;
  const float wz = l[6] * x + (l[7] * y + l[8] * z);
  return {static_cast<double>(wx + static_cast<float>(pose.translation[0])),
          static_cast<double>(wy + static_cast<float>(pose.translation[1])),
          static_cast<double>(wz + static_cast<float>(pose.translation[2]))};
}

Vec3 poseAs(R r, const Pose& pose, const Vec3& p) {
  const std::array<double, 9>& l = pose.linear;
  const Vec3& t = pose.translation;
  switch (r) {
    case R::ZRowAsXY: {
      Vec3 w = raster::poseVertex(pose, p);
      w[2] = ((l[6] * p[0] + l[7] * p[1]) + l[8] * p[2]) + t[2];
      return w;
    }
    case R::RowsRightFirst:
      return {(l[0] * p[0] + (l[1] * p[1] + l[2] * p[2])) + t[0],
              (l[3] * p[0] + (l[4] * p[1] + l[5] * p[2])) + t[1],
              (l[6] * p[0] + (l[7] * p[1] + l[8] * p[2])) + t[2]};
    case R::TranslationFirst:
      return {((t[0] + l[0] * p[0]) + l[1] * p[1]) + l[2] * p[2],
              ((t[1] + l[3] * p[0]) + l[4] * p[1]) + l[5] * p[2],
              ((t[2] + l[6] * p[0]) + l[7] * p[1]) + l[8] * p[2]};
    case R::FmaPose:
      return {std::fma(l[2], p[2], std::fma(l[1], p[1], l[0] * p[0])) + t[0],
              std::fma(l[5], p[2], std::fma(l[4], p[1], l[3] * p[0])) + t[1],
              std::fma(l[6], p[0], std::fma(l[7], p[1], l[8] * p[2])) + t[2]};
    case R::FloatPose:
      return floatPose(pose, p);
    case R::LinearTransposed: {
      Pose transposed = pose;
      for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j)
          transposed.linear[3 * i + j] = l[3 * j + i];
      }
      return raster::poseVertex(transposed, p);
    }
    default:
      return raster::poseVertex(pose, p);
  }
}

// ---- the window mapping ---------------------------------------------------------------

WindowPosition floatWindow(const WindowMapping& m, const Vec3& w) {
  const auto f = [](double v) { return static_cast<float>(v); };
  const float u = f(w[static_cast<std::size_t>(m.axes[0])]);
  const float v = f(w[static_cast<std::size_t>(m.axes[1])]);
  const float d = f(w[static_cast<std::size_t>(m.axes[2])]);
  return {static_cast<double>((u - f(m.umin)) / f(m.urange) * f(m.width)),
          static_cast<double>((v - f(m.vmin)) / f(m.vrange) * f(m.height)),
          static_cast<double>((f(m.depthMax) - d) / f(m.depthRange))};
}

WindowPosition mapAs(R r, const WindowMapping& m, const Vec3& w) {
  const double u = w[static_cast<std::size_t>(m.axes[0])];
  const double v = w[static_cast<std::size_t>(m.axes[1])];
  const double d = w[static_cast<std::size_t>(m.axes[2])];
  WindowPosition p = raster::mapToWindow(m, w);
  switch (r) {
    case R::FloatWindow:
      return floatWindow(m, w);
    case R::WindowScaleFirst:
      p.x = (u - m.umin) * (m.width / m.urange);
      p.y = (v - m.vmin) * (m.height / m.vrange);
      return p;
    case R::WindowMultiplyFirst:
      p.x = (u - m.umin) * m.width / m.urange;
      p.y = (v - m.vmin) * m.height / m.vrange;
      return p;
    case R::DepthReciprocal:
      p.z = (m.depthMax - d) * (1.0 / m.depthRange);
      return p;
    case R::DepthFromMin:
      p.z = 1.0 - (d - (m.depthMax - m.depthRange)) / m.depthRange;
      return p;
    case R::DepthReversed:
      p.z = (d - (m.depthMax - m.depthRange)) / m.depthRange;
      return p;
    case R::AxesInverted: {
      WindowMapping inverted = m;
      for (std::size_t i = 0; i < 3; ++i)
        inverted.axes[static_cast<std::size_t>(m.axes[i])] = static_cast<int>(i);
      return raster::mapToWindow(inverted, w);
    }
    case R::YDown:
      p.y = ((m.vmin + m.vrange) - v) / m.vrange * m.height;
      return p;
    default:
      return p;
  }
}

// ---- snapping and the rounding of z -----------------------------------------------------

float snapAs(R r, double x) {
  constexpr double one = raster::kSubpixelOne;
  switch (r) {
    case R::SnapAfterFloat:
      return raster::snapToSubpixel(static_cast<double>(static_cast<float>(x)));
    case R::SnapHalfAway:
      return static_cast<float>(std::round(x * one) / one);
    case R::SnapHalfUp:
      return static_cast<float>(std::floor(x * one + 0.5) / one);
    case R::SnapThroughInteger:
      return static_cast<float>(static_cast<double>(std::llrint(x * one)) / one);
    default:
      return raster::snapToSubpixel(x);
  }
}

// z >= 0 here (a drawable position), but the roundings are written for either sign.
float roundDepthAs(R r, double z) {
  const float nearest = static_cast<float>(z);
  switch (r) {
    case R::DepthTruncate:
      if (std::fabs(static_cast<double>(nearest)) > std::fabs(z))
        return std::nextafter(nearest, 0.0f);
      return nearest;
    case R::DepthTiesAway: {
      if (static_cast<double>(nearest) == z)
        return nearest;
      // The two floats around z, toward and away from zero; z is halfway when it is their mean
      // (exact in double: two neighbouring floats' mean has one bit more than a float).
      const bool below = std::fabs(static_cast<double>(nearest)) < std::fabs(z);
      const float toward = below ? nearest : std::nextafter(nearest, 0.0f);
      const float away = std::nextafter(toward, std::signbit(z) ? -FLT_MAX : FLT_MAX);
      const double mid = (static_cast<double>(toward) + static_cast<double>(away)) / 2.0;
      return z == mid ? away : nearest;
    }
    case R::DepthFlushSubnormal:
      return std::fabs(nearest) < FLT_MIN ? 0.0f : nearest;
    default:
      return nearest;
  }
}

}  // namespace

std::span<const VertexStageReadingInfo> wrongVertexStageReadings() {
  return kWrong;
}

std::string_view vertexStageReadingName(VertexStageReading reading) {
  if (reading == VertexStageReading::Contract)
    return "contract";
  for (const VertexStageReadingInfo& info : kWrong) {
    if (info.reading == reading)
      return info.name;
  }
  throw std::invalid_argument("unknown vertex-stage reading");
}

raster::WindowVertex vertexStageAs(VertexStageReading reading,
                                   const raster::VertexTransform& transform,
                                   const std::array<double, 3>& local) {
  if (reading == VertexStageReading::Contract)
    return raster::vertexStage(transform, local);
  const WindowPosition p = mapAs(reading, transform.window, poseAs(reading, transform.pose, local));
  return {snapAs(reading, p.x), snapAs(reading, p.y), roundDepthAs(reading, p.z)};
}

bool sameBits(const raster::WindowVertex& a, const raster::WindowVertex& b) {
  return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
         std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
         std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

}  // namespace recode::kit
