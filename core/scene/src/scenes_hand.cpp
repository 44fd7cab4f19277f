// Two hands grasping a ball (the paper's Figure 11 and Table 2). Each hand is a palm (a flat
// ellipsoid) and five fingers of three phalanges (capped cones), every block convex; each
// knuckle is a joint turning at its own rate. The fingers close on the ball and each stops
// where it meets it: for every finger the generator finds, by GJK distance in object space
// and bisection, the moment t the finger first touches the ball, and limits its joints at
// the angles of t + kPassFraction frames. So every finger reaches the ball, and none passes
// into it by more than one frame's motion; the run ends when the last finger has stopped.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/convex_distance.hpp"
#include "recode/scene/motion.hpp"
#include "scene_builder.hpp"

namespace recode::core::detail {

namespace {

constexpr double kBallRadius = 1.0;
constexpr double kHandOffset = 1.45;  // palm centre from the ball's centre along x
// How far past first contact a finger goes, in frames of its motion: enough to show as
// interfering pixels, less than one frame.
constexpr double kPassFraction = 0.9;

struct FingerSpec {
  const char* name;
  Eigen::Vector3d base;  // in the hand's coordinates
  bool thumb;            // points down (-z) and curls up under the ball
  std::array<double, 3> length;
  std::array<double, 3> rate;  // degrees per frame, proximal to distal
};

// Left hand: the palm faces +x (the ball); fingers point up and curl toward +x.
const FingerSpec kFingers[] = {
    {"thumb", {0.06, 0.30, -0.50}, true, {0.42, 0.32, 0.24}, {0.7, 0.6, 0.5}},
    {"index", {0.04, 0.39, 0.58}, false, {0.50, 0.32, 0.24}, {0.7, 0.6, 0.5}},
    {"middle", {0.04, 0.13, 0.62}, false, {0.55, 0.34, 0.25}, {0.7, 0.6, 0.5}},
    {"ring", {0.04, -0.13, 0.60}, false, {0.50, 0.32, 0.24}, {0.7, 0.6, 0.5}},
    {"little", {0.04, -0.39, 0.54}, false, {0.42, 0.28, 0.20}, {0.7, 0.6, 0.5}},
};
constexpr std::array<double, 3> kRadius0 = {0.085, 0.075, 0.068};  // at the knuckle
constexpr std::array<double, 3> kRadius1 = {0.075, 0.068, 0.060};  // toward the tip
const char* const kPhalanxNames[] = {"proximal", "middle", "distal"};

Eigen::Isometry3d placement(const Eigen::Vector3d& position, const Eigen::Vector3d& degrees) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotationFromDegrees(degrees);
  t.translation() = position;
  return t;
}

Eigen::Isometry3d hinge(double degrees) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotationAboutAxisDegrees(Eigen::Vector3d::UnitY(), degrees);
  return t;
}

struct Finger {
  FingerSpec spec;
  std::array<Block, 3> blocks;
  Eigen::Isometry3d base;  // finger base -> world
  double touch = 0.0;      // first touching time, frames
  double stop = 0.0;       // the time it stops at
};

// The finger's three phalanges in world coordinates at time t (frames, not rounded): the same
// composition as SceneObject::poseAt, parent * rest * joint, with the angles rate * t.
std::array<std::vector<Eigen::Vector3d>, 3> fingerAt(const Finger& f, double t) {
  std::array<std::vector<Eigen::Vector3d>, 3> out;
  Eigen::Isometry3d frame = f.base;
  for (int i = 0; i < 3; ++i) {
    if (i > 0)
      frame = frame * placement({0, 0, f.spec.length[static_cast<std::size_t>(i - 1)]},
                                Eigen::Vector3d::Zero());
    frame = frame * hinge(f.spec.rate[static_cast<std::size_t>(i)] * t);
    for (const Eigen::Vector3d& v : f.blocks[static_cast<std::size_t>(i)].mesh.vertices)
      out[static_cast<std::size_t>(i)].push_back(frame.linear() * v + frame.translation());
  }
  return out;
}

bool touches(const Finger& f, double t, const std::vector<Eigen::Vector3d>& ball) {
  for (const auto& phalanx : fingerAt(f, t))
    if (convexHullDistance(phalanx, ball) <= 0.0)
      return true;
  return false;
}

// The first time the finger touches the ball, to 1e-9 frames.
double firstTouch(const Finger& f, const std::vector<Eigen::Vector3d>& ball) {
  if (touches(f, 0.0, ball))
    throw std::logic_error("hand-grasp: the " + std::string(f.spec.name) +
                           " touches the ball at frame 0");
  for (int k = 1; k <= 1000; ++k) {
    if (!touches(f, k, ball))
      continue;
    double lo = k - 1, hi = k;
    while (hi - lo > 1e-9) {
      const double mid = 0.5 * (lo + hi);
      (touches(f, mid, ball) ? hi : lo) = mid;
    }
    return hi;
  }
  throw std::logic_error("hand-grasp: the " + std::string(f.spec.name) + " never reaches the ball");
}

Json fingerJson(const Finger& f) {
  // proximal { phalanx, middle { phalanx, distal } }, built from the tip inward.
  Json inner;
  for (int i = 2; i >= 0; --i) {
    const std::size_t u = static_cast<std::size_t>(i);
    Json joint;
    joint["axis"] = vec(0, 1, 0);
    joint["rate_deg"] = f.spec.rate[u];
    joint["min_deg"] = 0.0;
    joint["max_deg"] = tidy(f.spec.rate[u] * f.stop);
    Json node;
    node["name"] = kPhalanxNames[u];
    if (i > 0)
      node["position"] = vec(0, 0, f.spec.length[u - 1]);
    node["joint"] = joint;
    if (i == 2) {
      node["shape"] = f.blocks[u].shape;
    } else {
      Json bone;
      bone["name"] = "phalanx";
      bone["shape"] = f.blocks[u].shape;
      node["children"] = Json::array({bone, inner});
    }
    inner = node;
  }
  Json finger;
  finger["name"] = f.spec.name;
  finger["position"] = vec(f.spec.base.x(), f.spec.base.y(), f.spec.base.z());
  if (f.spec.thumb)
    finger["rotation_deg"] = vec(180, 0, 0);
  finger["children"] = Json::array({inner});
  return finger;
}

}  // namespace

Json makeHandGraspScene(int trianglesPerBlock) {
  const Block ball = sphereBlock(kBallRadius, trianglesPerBlock);
  const Block palm = ellipsoidBlock(0.12, 0.55, 0.62, trianglesPerBlock);
  Json objects = Json::array();
  int lastFrame = 0;
  for (int side = 0; side < 2; ++side) {
    // The right hand is the left one turned half a turn about z.
    const Eigen::Vector3d handPosition(side ? kHandOffset : -kHandOffset, 0, 0);
    const Eigen::Vector3d handRotation(0, 0, side ? 180 : 0);
    const Eigen::Isometry3d hand = placement(handPosition, handRotation);
    Json children = Json::array();
    Json palmNode;
    palmNode["name"] = "palm";
    palmNode["shape"] = palm.shape;
    children.push_back(palmNode);
    for (const FingerSpec& spec : kFingers) {
      Finger f;
      f.spec = spec;
      for (std::size_t i = 0; i < 3; ++i) {
        const double tip = i == 2 ? spec.length[2] : spec.length[i];
        f.blocks[i] = cappedConeBlock(kRadius0[i], kRadius1[i], tip, trianglesPerBlock);
      }
      f.base = hand * placement(spec.base, Eigen::Vector3d(spec.thumb ? 180 : 0, 0, 0));
      f.touch = firstTouch(f, ball.mesh.vertices);
      f.stop = f.touch + kPassFraction;
      // The frame at which the slowest joint reaches its limit.
      int stopFrame = 0;
      for (std::size_t i = 0; i < 3; ++i)
        stopFrame = std::max(
            stopFrame, static_cast<int>(std::ceil(tidy(spec.rate[i] * f.stop) / spec.rate[i])));
      lastFrame = std::max(lastFrame, stopFrame);
      children.push_back(fingerJson(f));
    }
    Json h;
    h["name"] = side ? "right hand" : "left hand";
    h["position"] = vec(handPosition.x(), handPosition.y(), handPosition.z());
    if (side)
      h["rotation_deg"] = vec(0, 0, 180);
    h["children"] = children;
    objects.push_back(h);
  }
  Json ballNode;
  ballNode["name"] = "ball";
  ballNode["shape"] = ball.shape;
  objects.push_back(ballNode);

  Json scene;
  Json view;
  view["axis"] = "z";  // from above: the fingers meet the ball's top and bottom face on
  view["pixel_size"] = 0.004;
  scene["view"] = view;
  scene["frames"] = lastFrame + 1;
  scene["objects"] = objects;
  return scene;
}

}  // namespace recode::core::detail
