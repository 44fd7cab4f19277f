#include "recode/refine/view_axis_choice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace recode::core {

namespace {

int indexOf(ViewAxis axis) {
  return static_cast<int>(axis);
}

ViewAxis axisOf(int index) {
  return static_cast<ViewAxis>(index);
}

// The axis of the best score (`better(s, t)`: s beats t), the scene axis on a tie with the
// best, otherwise the first of the best in x, y, z order.
template <class Better>
ViewAxis bestAxis(const std::array<double, 3>& score, ViewAxis sceneAxis, Better better) {
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (better(score[static_cast<std::size_t>(i)], score[static_cast<std::size_t>(best)]))
      best = i;
  const double scene = score[static_cast<std::size_t>(indexOf(sceneAxis))];
  if (!better(score[static_cast<std::size_t>(best)], scene))
    return sceneAxis;
  return axisOf(best);
}

// The world-axis direction of least overlap between two OBBs over the 15 separating-axis
// candidates (the most negative overlap when they are apart). Cross products of nearly
// parallel edges have no reliable direction and are skipped.
Eigen::Vector3d leastOverlapDirection(const Obb& a, const Obb& b) {
  std::vector<Eigen::Vector3d> candidates;
  for (int i = 0; i < 3; ++i) {
    candidates.push_back(a.axes.col(i));
    candidates.push_back(b.axes.col(i));
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d c = a.axes.col(i).cross(b.axes.col(j));
      if (c.norm() > 1e-6)
        candidates.push_back(c.normalized());
    }
  const Eigen::Vector3d d = b.center - a.center;
  Eigen::Vector3d best = candidates.front();
  double bestOverlap = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& l : candidates) {
    double ra = 0.0, rb = 0.0;
    for (int i = 0; i < 3; ++i) {
      ra += a.halfExtents[i] * std::fabs(a.axes.col(i).dot(l));
      rb += b.halfExtents[i] * std::fabs(b.axes.col(i).dot(l));
    }
    const double overlap = ra + rb - std::fabs(d.dot(l));
    if (overlap < bestOverlap) {
      bestOverlap = overlap;
      best = l;
    }
  }
  return best;
}

// Every rule, ViewAxisRule::Scene first; parsing and the list of names both come from here.
constexpr ViewAxisRule kAllViewAxisRules[] = {ViewAxisRule::Scene, ViewAxisRule::FewestMor,
                                              ViewAxisRule::WidestOverlap, ViewAxisRule::Separating,
                                              ViewAxisRule::ThinOverlap};
// The name that stands for kAdaptiveViewAxisRule.
constexpr std::string_view kAdaptiveRuleName = "adaptive";

}  // namespace

std::string_view toString(ViewAxisRule rule) {
  switch (rule) {
    case ViewAxisRule::Scene:
      return "scene";
    case ViewAxisRule::FewestMor:
      return "fewest-mor";
    case ViewAxisRule::WidestOverlap:
      return "widest-overlap";
    case ViewAxisRule::Separating:
      return "separating";
    case ViewAxisRule::ThinOverlap:
      return "thin-overlap";
  }
  return "?";
}

std::optional<ViewAxisRule> parseViewAxisRule(std::string_view name) {
  if (name == kAdaptiveRuleName)
    return kAdaptiveViewAxisRule;
  for (const ViewAxisRule rule : kAllViewAxisRules)
    if (name == toString(rule))
      return rule;
  return std::nullopt;
}

std::string_view viewAxisRuleNames() {
  // "scene" first, then the alias "adaptive", then the other rules in declaration order.
  static const std::string names = [] {
    std::string list(toString(kAllViewAxisRules[0]));
    list += ", ";
    list += kAdaptiveRuleName;
    for (std::size_t k = 1; k < std::size(kAllViewAxisRules); ++k) {
      list += ", ";
      list += toString(kAllViewAxisRules[k]);
    }
    return list;
  }();
  return names;
}

AxisChoiceInput axisChoiceInput(const TriangleMesh& a, const TriangleMesh& b, double pixelSize) {
  return {boundingBox(a), boundingBox(b), fitObb(a.vertices), fitObb(b.vertices), pixelSize};
}

double framePixelSize(const FrameSpec& frame) {
  return std::max((frame.window.umax - frame.window.umin) / frame.width,
                  (frame.window.vmax - frame.window.vmin) / frame.height);
}

ViewAxis chooseViewAxis(ViewAxisRule rule, ViewAxis sceneAxis, const AxisChoiceInput& input) {
  if (rule == ViewAxisRule::Scene || !aabbsOverlap(input.boxA, input.boxB))
    return sceneAxis;
  std::array<double, 3> width{};  // of the boxes' intersection, >= 0 as they overlap
  for (int i = 0; i < 3; ++i)
    width[static_cast<std::size_t>(i)] = std::min(input.boxA.max[i], input.boxB.max[i]) -
                                         std::max(input.boxA.min[i], input.boxB.min[i]);
  switch (rule) {
    case ViewAxisRule::Scene:
      break;
    case ViewAxisRule::FewestMor:
      return bestAxis(width, sceneAxis, [](double s, double t) { return s > t; });
    case ViewAxisRule::WidestOverlap:
      return bestAxis(width, sceneAxis, [](double s, double t) { return s < t; });
    case ViewAxisRule::ThinOverlap: {
      const auto scene = static_cast<std::size_t>(indexOf(sceneAxis));
      const double across = std::min(width[(scene + 1) % 3], width[(scene + 2) % 3]);
      if (across >= kThinOverlapPixels * input.pixelSize)
        return sceneAxis;
      return bestAxis(width, sceneAxis, [](double s, double t) { return s < t; });
    }
    case ViewAxisRule::Separating: {
      const Eigen::Vector3d l = leastOverlapDirection(input.obbA, input.obbB);
      return bestAxis({std::fabs(l.x()), std::fabs(l.y()), std::fabs(l.z())}, sceneAxis,
                      [](double s, double t) { return s > t; });
    }
  }
  return sceneAxis;
}

FrameSpec frameAlongAxis(const FrameSpec& base, ViewAxis axis, const Aabb& bounds) {
  if (axis == base.axis)
    return base;
  return frameFromPixelSize(axis, defaultWindow(axis, bounds, std::nullopt), framePixelSize(base));
}

}  // namespace recode::core
