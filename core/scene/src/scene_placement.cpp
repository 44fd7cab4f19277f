// Placement and motion of a node: position, rotation_deg, motion, keyframes, joint.
#include <climits>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene_reader.hpp"

namespace recode::core::detail {

namespace {

// The rules quoted in messages (scene.hpp: why each range keeps poses finite).
constexpr std::string_view kCoordinateRule = "world units";
constexpr std::string_view kSpeedRule =
    "world units per frame, so that 1,000,000 frames stay finite";
constexpr std::string_view kAngleRule = "degrees";
constexpr std::string_view kRateRule = "degrees per frame, so that 1,000,000 frames stay finite";
constexpr std::string_view kDirectionRule = "a direction";

}  // namespace

using recode::json::childPath;
using recode::json::describeJsonValue;
using recode::json::jsonText;

void PlacementReader::read(const json& v, const std::string& path, Placement& placement) const {
  if (v.contains("position"))
    placement.position =
        vector3(v.at("position"), childPath(path, "position"), kMaxCoordinate, kCoordinateRule);
  if (v.contains("rotation_deg"))
    placement.rotationDeg =
        vector3(v.at("rotation_deg"), childPath(path, "rotation_deg"), kMaxAngleDeg, kAngleRule);
  if (v.contains("motion") && v.contains("keyframes"))
    fields_.fail(path, "give at most one of \"motion\" and \"keyframes\"");
  if (v.contains("motion"))
    placement.motion = motion(v.at("motion"), childPath(path, "motion"), placement.position);
  if (v.contains("keyframes"))
    placement.keyframes = keyframes(v.at("keyframes"), childPath(path, "keyframes"), placement);
  if (v.contains("joint"))
    placement.joint = joint(v.at("joint"), childPath(path, "joint"));
}

Motion PlacementReader::motion(const json& v, const std::string& path,
                               const Eigen::Vector3d& position) const {
  fields_.requireObject(v, path);
  fields_.requireOnlyKeys(v, path, {"velocity", "angular_velocity_deg", "bounce_within"});
  Motion m;
  if (v.contains("velocity"))
    m.velocity = vector3(v.at("velocity"), childPath(path, "velocity"), kMaxSpeed, kSpeedRule);
  if (v.contains("angular_velocity_deg")) {
    m.angularVelocityDeg =
        vector3(v.at("angular_velocity_deg"), childPath(path, "angular_velocity_deg"),
                kMaxAngularRateDeg, kRateRule);
  }
  if (v.contains("bounce_within"))
    m.bounceWithin = bounceBox(v.at("bounce_within"), childPath(path, "bounce_within"), position);
  return m;
}

// The box must be well formed and hold the object's starting position.
Aabb PlacementReader::bounceBox(const json& v, const std::string& path,
                                const Eigen::Vector3d& position) const {
  const json& box =
      fields_.arrayOfSize(v, path, 2, "2 corners [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
  Aabb bounds;
  bounds.min = vector3(box[0], childPath(path, 0), kMaxCoordinate, kCoordinateRule);
  bounds.max = vector3(box[1], childPath(path, 1), kMaxCoordinate, kCoordinateRule);
  for (int i = 0; i < 3; ++i) {
    if (!(bounds.min[i] <= bounds.max[i])) {
      fields_.fail(path, "the first corner must not exceed the second (" +
                             jsonText(box[0][static_cast<std::size_t>(i)]) + " > " +
                             jsonText(box[1][static_cast<std::size_t>(i)]) + " along " + "xyz"[i] +
                             ")");
    }
    if (!(bounds.min[i] <= position[i] && position[i] <= bounds.max[i])) {
      fields_.fail(path, "the object's position " + jsonText(json(position[i])) + " along " +
                             "xyz"[i] + " lies outside the box");
    }
  }
  return bounds;
}

// Keys without a position or rotation keep the node's rest values.
std::vector<Keyframe> PlacementReader::keyframes(const json& v, const std::string& path,
                                                 const Placement& rest) const {
  if (!v.is_array())
    fields_.fail(path, "expected an array of keyframes, got " + describeJsonValue(v));
  if (v.empty())
    fields_.fail(path, "expected at least one keyframe, got an empty array");
  std::vector<Keyframe> keys;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string p = childPath(path, i);
    const json& k = v[i];
    fields_.requireObject(k, p);
    fields_.requireOnlyKeys(k, p, {"frame", "position", "rotation_deg"});
    if (!k.contains("frame"))
      fields_.fail(p, "missing key \"frame\"");
    Keyframe key;
    key.frame =
        static_cast<int>(fields_.integerInRange(k.at("frame"), childPath(p, "frame"), 0, INT_MAX));
    if (!keys.empty() && key.frame <= keys.back().frame) {
      fields_.fail(childPath(p, "frame"), "keyframes must be in increasing frame order; got " +
                                              std::to_string(key.frame) + " after " +
                                              std::to_string(keys.back().frame));
    }
    key.position = k.contains("position") ? vector3(k.at("position"), childPath(p, "position"),
                                                    kMaxCoordinate, kCoordinateRule)
                                          : rest.position;
    key.rotationDeg =
        k.contains("rotation_deg")
            ? vector3(k.at("rotation_deg"), childPath(p, "rotation_deg"), kMaxAngleDeg, kAngleRule)
            : rest.rotationDeg;
    keys.push_back(key);
  }
  return keys;
}

Joint PlacementReader::joint(const json& v, const std::string& path) const {
  fields_.requireObject(v, path);
  fields_.requireOnlyKeys(v, path, {"axis", "angle_deg", "rate_deg", "min_deg", "max_deg"});
  if (!v.contains("axis"))
    fields_.fail(path, "missing key \"axis\" (the hinge direction [x, y, z])");
  Joint j;
  const std::string axisPath = childPath(path, "axis");
  const Eigen::Vector3d axis = vector3(v.at("axis"), axisPath, kMaxCoordinate, kDirectionRule);
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    fields_.fail(axisPath, "expected a non-zero direction, got " + jsonText(v.at("axis")));
  j.axis = axis / length;
  if (v.contains("angle_deg"))
    j.angleDeg = angle(v.at("angle_deg"), childPath(path, "angle_deg"));
  if (v.contains("rate_deg")) {
    j.rateDeg = fields_.numberInRange(v.at("rate_deg"), childPath(path, "rate_deg"),
                                      -kMaxAngularRateDeg, kMaxAngularRateDeg, kRateRule);
  }
  if (v.contains("min_deg"))
    j.minDeg = angle(v.at("min_deg"), childPath(path, "min_deg"));
  if (v.contains("max_deg"))
    j.maxDeg = angle(v.at("max_deg"), childPath(path, "max_deg"));
  if (j.minDeg && j.maxDeg && *j.minDeg > *j.maxDeg) {
    fields_.fail(path, "min_deg (" + jsonText(v.at("min_deg")) + ") must not exceed max_deg (" +
                           jsonText(v.at("max_deg")) + ")");
  }
  if ((j.minDeg && j.angleDeg < *j.minDeg) || (j.maxDeg && j.angleDeg > *j.maxDeg)) {
    fields_.fail(childPath(path, "angle_deg"),
                 "the starting angle " + jsonText(json(j.angleDeg)) + " lies outside [" +
                     (j.minDeg ? jsonText(json(*j.minDeg)) : std::string("-inf")) + ", " +
                     (j.maxDeg ? jsonText(json(*j.maxDeg)) : std::string("inf")) +
                     "] (min_deg, max_deg)");
  }
  return j;
}

Eigen::Vector3d PlacementReader::vector3(const json& v, const std::string& path, double limit,
                                         std::string_view why) const {
  fields_.arrayOfSize(v, path, 3, "3 numbers [x, y, z]");
  Eigen::Vector3d x;
  for (std::size_t i = 0; i < 3; ++i)
    x[static_cast<Eigen::Index>(i)] =
        fields_.numberInRange(v[i], childPath(path, i), -limit, limit, why);
  return x;
}

double PlacementReader::angle(const json& v, const std::string& path) const {
  return fields_.numberInRange(v, path, -kMaxAngleDeg, kMaxAngleDeg, kAngleRule);
}

}  // namespace recode::core::detail
