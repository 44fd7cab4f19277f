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

#include "recode/core/mesh.hpp"
#include "recode/core/view.hpp"

namespace recode::core {

// "<file>: <json path>: <problem>", e.g. "pair.json: objects[1].shape.radius: expected a
// positive number, got -2". The JSON path is also available on its own.
class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& file, const std::string& jsonPath, const std::string& problem);
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& jsonPath() const { return jsonPath_; }

 private:
  std::string file_;
  std::string jsonPath_;
};

// Per-frame motion; frame k's pose is a pure function of k (used by `recode run`).
struct Motion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // world units per frame
  Eigen::Vector3d angularVelocityDeg = Eigen::Vector3d::Zero();  // degrees per frame, X Y Z
};

struct SceneObject {
  std::string name;         // "name", or "object <index>" when the file gives none
  std::string jsonPath;     // "objects[<index>]", for messages
  TriangleMesh localMesh;   // in the object's own frame, validated closed and convex
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();  // applied X, then Y, then Z
  std::optional<Motion> motion;

  // The rigid transform local -> world: x' = R p + position with R = Rz * Ry * Rx.
  [[nodiscard]] Eigen::Isometry3d pose() const;
  // localMesh moved by pose().
  [[nodiscard]] TriangleMesh worldMesh() const;
};

// The "view" object. Window and resolution are optional in the file; resolveFrame() in
// frame.hpp fills in the defaults.
struct ViewSpec {
  ViewAxis axis = ViewAxis::Z;
  std::optional<ViewWindow> window;               // "window": [umin, vmin, umax, vmax]
  std::optional<std::array<int, 2>> resolution;   // "resolution": [W, H]
  std::optional<double> pixelSize;                // "pixel_size": world units per pixel
};

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
