#pragma once
// Scene files (DESIGN.md section 6, documented field by field in docs/scenes.md): the view,
// and a list of objects, each a convex block given by a mesh file or a shape generator and
// placed by a position and a rotation. Loading checks every field; any problem throws
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

// Per-frame motion; frame k's pose is a pure function of k (used by `recode run`).
struct Motion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // world units per frame
  Eigen::Vector3d angularVelocityDeg = Eigen::Vector3d::Zero();  // degrees per frame, X Y Z
};

struct SceneObject {
  std::string name;        // "name", or "object <index>" when the file gives none
  std::string jsonPath;    // "objects[<index>]", for messages
  TriangleMesh localMesh;  // in the object's own frame, validated closed and convex
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();  // applied X, then Y, then Z
  std::optional<Motion> motion;

  // The rigid transform local -> world: x' = R p + position with R = Rz * Ry * Rx.
  [[nodiscard]] Eigen::Isometry3d pose() const;
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
