#pragma once
// Scene files (documented field by field in docs/scenes.md): the view,
// and a list of objects, each a convex block given by a mesh file or a shape generator, or a
// tree of such blocks ("children"), placed by a position and a rotation and moved per frame
// by a motion, keyframes or a joint. Loading checks every field; any problem throws
// SceneError whose message names the file, the JSON path and what is wrong.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/projection.hpp"
#include "recode/json/error.hpp"
#include "recode/scene/motion.hpp"

namespace recode::core {

// "<file>: <json path>: <problem>", e.g. "pair.json: objects[1].shape.radius: expected a
// positive number, got -2". The JSON path is also available on its own.
// A problem with the file as a whole has an empty JSON path and reads "<file>: <problem>";
// malformed JSON reads "<file>:<line>:<column>: invalid JSON: ..." (line() and column() are
// then 1-based, counted in bytes; both are 0 for every other error). The message and its
// parts are those of the JSON reading layer's error, which the scene reader's become.
class SceneError : public recode::json::JsonError {
 public:
  using recode::json::JsonError::JsonError;
  explicit SceneError(const recode::json::JsonError& error) : recode::json::JsonError(error) {}
};

// A node of an object: a block (a leaf, with localMesh) or a group of child nodes placed
// relative to it (its Placement: rest pose, motion, keyframes, joint). The objects of a scene
// are the roots. A leaf is a convex block, or with `closed` a closed mesh of any shape, which
// the layered pair decides (docs/algorithm.md section 13).
struct SceneObject : Placement {
  std::string name;        // "name", or "object <index>" / "child <index>" when not given
  std::string jsonPath;    // "objects[<index>]", "objects[0].children[2]", for messages
  TriangleMesh localMesh;  // leaves: in the node's own frame, validated (convex unless closed)
  bool closed = false;     // leaves: a closed mesh ("closed": true, or a torus shape)
  std::vector<SceneObject> children;  // empty for a leaf

  [[nodiscard]] bool isLeaf() const { return children.empty(); }
  // localMesh moved by pose().
  [[nodiscard]] TriangleMesh worldMesh() const;
};

// The most frames a scene file or `recode run --frames` may ask for: a million frames of the
// smallest scene already take minutes, and a larger count is far more likely a typo.
inline constexpr int kMaxFrames = 1'000'000;

// The ranges of a scene's numbers (docs/scenes.md, "Ranges"). Each keeps every pose finite, and
// far from overflow, over kMaxFrames frames: a position moves at most kMaxSpeed * kMaxFrames =
// 1e9 from its start, an angle turns at most 1e12 degrees (reduced exactly modulo 360), and the
// norm of an angular velocity (a sum of squares) stays finite. Without them an angular velocity
// of 1e160 squared to infinity and posed every node at NaN.
inline constexpr double kMaxCoordinate = 1e9;      // world units: positions, window, boxes, sizes
inline constexpr double kMaxSpeed = 1e3;           // world units per frame: velocity components
inline constexpr double kMaxAngleDeg = 1e6;        // degrees: rotation_deg, joint angles
inline constexpr double kMaxAngularRateDeg = 1e6;  // degrees per frame: angular velocity, rate_deg
// The smallest side of a view window, world units: smaller, the objects of any ordinary scene
// map far beyond the rasterizer's coordinate range.
inline constexpr double kMinWindowSide = 1e-6;

// The most triangles the blocks of one scene may have together, each use of a part counted
// again: 2^25, as for one generated shape (about 1 GiB of meshes). Without it a few lines of
// parts and shapes asked for billions of triangles and ran until memory ran out.
inline constexpr std::size_t kMaxSceneTriangles = std::size_t{1} << 25;

// What reading one scene may build. A program that reads scenes from untrusted sources can
// lower it; a generated shape is refused from its parameters, before it is built.
struct SceneReadLimits {
  std::size_t maxTriangles = kMaxSceneTriangles;
};

// ViewSpec (the "view" object) is declared in recode/geometry/projection.hpp.

struct Scene {
  std::string sourceName;  // the file name as given, for messages
  ViewSpec view;
  std::vector<SceneObject> objects;
  std::optional<int> frames;  // "frames", 1..kMaxFrames
};

// Reads and checks a scene file. Mesh paths are relative to the scene file's directory.
[[nodiscard]] Scene loadScene(const std::filesystem::path& file,
                              const SceneReadLimits& limits = {});

// Parses scene JSON text. `sourceName` is used in messages; `baseDir` resolves mesh paths.
[[nodiscard]] Scene parseScene(std::string_view jsonText, const std::string& sourceName,
                               const std::filesystem::path& baseDir,
                               const SceneReadLimits& limits = {});

// Refuses a scene with a closed-mesh leaf where only convex blocks are decided (`who`, e.g.
// "recode run"): throws SceneError naming the first such leaf's JSON path and `who`.
void requireConvexBlocks(const Scene& scene, std::string_view who);

}  // namespace recode::core
