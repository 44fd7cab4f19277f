#pragma once
// Scene files (DESIGN.md section 6, documented field by field in docs/scenes.md): the view,
// and a list of objects, each a convex block given by a mesh file or a shape generator, or a
// tree of such blocks ("children"), placed by a position and a rotation and moved per frame
// by a motion, keyframes or a joint. Loading checks every field; any problem throws
// SceneError whose message names the file, the JSON path and what is wrong.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "recode/core/frame.hpp"
#include "recode/core/mesh.hpp"
#include "recode/core/view.hpp"

namespace recode::core {

// "<file>: <json path>: <problem>", e.g. "pair.json: objects[1].shape.radius: expected a
// positive number, got -2". The JSON path is also available on its own.
// A problem with the file as a whole has an empty JSON path and reads "<file>: <problem>";
// malformed JSON reads "<file>:<line>:<column>: invalid JSON: ..." (line() and column() are
// then 1-based, counted in bytes; both are 0 for every other error).
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& jsonPath, const std::string& problem);
  SceneError(const std::string& file, int line, int column, const std::string& problem);
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& jsonPath() const { return jsonPath_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] int column() const { return column_; }

 private:
  std::string file_;
  std::string jsonPath_;
  int line_ = 0;
  int column_ = 0;
};

// Per-frame motion; frame k's pose is a pure function of k (used by `recode run`, see
// motion.hpp for the formulas).
struct Motion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // world units per frame
  Eigen::Vector3d angularVelocityDeg = Eigen::Vector3d::Zero();  // degrees per frame, X Y Z
  // "bounce_within": the node's origin reflects off the walls of this box (its parent's
  // coordinates) instead of leaving it. Absent: straight-line motion.
  std::optional<Aabb> bounceWithin;
};

// A pose at a given frame ("keyframes"); between two keyframes the position is interpolated
// linearly and the rotation by spherical linear interpolation.
struct Keyframe {
  int frame = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();
};

// A hinge: the node turns about `axis` (a unit vector in the node's own coordinates, through
// its origin) by angle(k) = clamp(angleDeg + rateDeg * k, minDeg, maxDeg) degrees.
struct Joint {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double angleDeg = 0.0;
  double rateDeg = 0.0;
  std::optional<double> minDeg;  // absent: no lower limit
  std::optional<double> maxDeg;  // absent: no upper limit
};

// A node of an object: a convex block (a leaf, with localMesh) or a group of child nodes
// placed relative to it. The objects of a scene are the roots.
struct SceneObject {
  std::string name;        // "name", or "object <index>" / "child <index>" when not given
  std::string jsonPath;    // "objects[<index>]", "objects[0].children[2]", for messages
  TriangleMesh localMesh;  // leaves: in the node's own frame, validated closed and convex
  std::vector<SceneObject> children;  // empty for a leaf
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();  // applied X, then Y, then Z
  std::optional<Motion> motion;
  std::vector<Keyframe> keyframes;  // empty: none; never together with motion
  std::optional<Joint> joint;

  [[nodiscard]] bool isLeaf() const { return children.empty(); }
  // The rest transform local -> parent (world for a root): x' = R p + position with
  // R = Rz * Ry * Rx. Motion, keyframes and joint are not applied (see poseAt).
  [[nodiscard]] Eigen::Isometry3d pose() const;
  // The transform local -> parent at frame k, with motion, keyframes and joint applied
  // (defined in motion.cpp; a pure function of k).
  [[nodiscard]] Eigen::Isometry3d poseAt(int frame) const;
  // True if poseAt(k) depends on k.
  [[nodiscard]] bool moves() const;
  // localMesh moved by pose().
  [[nodiscard]] TriangleMesh worldMesh() const;
};

// ViewSpec (the "view" object) is declared in frame.hpp, beside resolveFrame().

struct Scene {
  std::string sourceName;  // the file name as given, for messages
  ViewSpec view;
  std::vector<SceneObject> objects;
  std::optional<int> frames;  // "frames"
};

// Rotation matrix for rotation_deg: about X by rx, then Y by ry, then Z by rz (fixed axes),
// i.e. Rz * Ry * Rx. Angles that are whole multiples of 90 degrees give exact 0 / +-1
// entries, so axis-aligned scenes stay exactly axis-aligned.
[[nodiscard]] Eigen::Matrix3d rotationFromDegrees(const Eigen::Vector3d& degrees);

// Reads and checks a scene file. Mesh paths are relative to the scene file's directory.
[[nodiscard]] Scene loadScene(const std::filesystem::path& file);

// Parses scene JSON text. `sourceName` is used in messages; `baseDir` resolves mesh paths.
[[nodiscard]] Scene parseScene(std::string_view jsonText, const std::string& sourceName,
                               const std::filesystem::path& baseDir);

}  // namespace recode::core
