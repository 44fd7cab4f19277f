#pragma once
// The scene reader (private to recode::scene), one reader per section of the schema
// (docs/scenes.md): the view, objects and their tree, parts, shapes and meshes, placement and
// motion. They share the JSON reading layer's field reader, so that every error names the file
// and the JSON path the same way.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "recode/json/document.hpp"
#include "recode/scene/scene.hpp"

namespace recode::core::detail {

using nlohmann::json;
using recode::json::JsonFieldReader;

// The "view" object (scene_view.cpp).
[[nodiscard]] ViewSpec readView(const JsonFieldReader& fields, const json& v,
                                const std::string& path);

// The triangles of a scene's blocks so far, against SceneReadLimits::maxTriangles
// (scene_objects.cpp).
class TriangleBudget {
 public:
  TriangleBudget(const JsonFieldReader& fields, std::size_t limit)
      : fields_(fields), limit_(limit) {}

  // Refuses, at `path`, a block that would have `triangles` more (a count predicted from a
  // shape's parameters, so possibly huge) before it is built.
  void check(double triangles, const std::string& path) const;
  // Counts `triangles` more, made for the block at `path`, refusing the scene past the limit.
  void take(std::size_t triangles, const std::string& path);
  [[nodiscard]] std::size_t used() const { return used_; }

 private:
  const JsonFieldReader& fields_;
  std::size_t limit_;
  std::size_t used_ = 0;
};

// What a mesh file's faces are taken as: a convex block (validated convex), the convex hull of
// its vertices ("hull": true), or a closed mesh of any shape ("closed": true).
enum class MeshUse { ConvexBlock, Hull, Closed };

// A leaf's local mesh and whether it is a closed mesh (SceneObject::closed).
struct LeafMesh {
  TriangleMesh mesh;
  bool closed = false;
};

// The block of a leaf: its "mesh" file or its "shape", validated as what it is taken for
// (scene_shapes.cpp). Every block's triangles are counted in the scene's budget.
class ShapeReader {
 public:
  ShapeReader(const JsonFieldReader& fields, std::filesystem::path baseDir,
              TriangleBudget& triangles)
      : fields_(fields), baseDir_(std::move(baseDir)), triangles_(triangles) {}

  // The local mesh of a node (or part) `v` at `path` that has "mesh" or "shape" (a mesh
  // hulled when it says "hull": true, a closed mesh when it says "closed": true or is a torus).
  [[nodiscard]] LeafMesh leafMesh(const json& v, const std::string& path) const;
  // Refuses "hull", "parts_from_groups" and "closed" on a node without "mesh", that are not
  // booleans, or "closed" beside either of the others; returns "parts_from_groups" (false when
  // absent).
  [[nodiscard]] bool checkMeshOptions(const json& v, const std::string& path) const;
  // The blocks of a node with "mesh" and "parts_from_groups": true, one per OBJ object or
  // group (name, block), each validated, or hulled with "hull": true.
  [[nodiscard]] std::vector<std::pair<std::string, TriangleMesh>> meshGroups(
      const json& v, const std::string& path) const;

 private:
  // The block of a mesh file at `path` (the value of "mesh"), taken as `use`.
  [[nodiscard]] TriangleMesh meshFile(const json& v, const std::string& path, MeshUse use) const;
  // A block from a mesh read from `file`: its vertices within range, then validated as `use`
  // says (with a hint to use "hull" when a convex block fails) or replaced by their hull. `what`
  // names it in messages.
  [[nodiscard]] TriangleMesh meshBlock(TriangleMesh mesh, const std::string& what,
                                       const std::string& path, MeshUse use) const;
  // The shape's mesh; *typeName is set to its "type".
  [[nodiscard]] TriangleMesh shape(const json& v, const std::string& path,
                                   std::string* typeName) const;
  // The "type" of a shape, with only the keys that type allows.
  [[nodiscard]] std::string shapeType(const json& v, const std::string& path) const;

  const JsonFieldReader& fields_;
  std::filesystem::path baseDir_;
  TriangleBudget& triangles_;
};

// position, rotation_deg, motion, keyframes, joint (scene_placement.cpp).
class PlacementReader {
 public:
  explicit PlacementReader(const JsonFieldReader& fields) : fields_(fields) {}

  // The placement keys of node `v` at `path`, into `placement`.
  void read(const json& v, const std::string& path, Placement& placement) const;

 private:
  [[nodiscard]] Motion motion(const json& v, const std::string& path,
                              const Eigen::Vector3d& position) const;
  [[nodiscard]] Aabb bounceBox(const json& v, const std::string& path,
                               const Eigen::Vector3d& position) const;
  [[nodiscard]] std::vector<Keyframe> keyframes(const json& v, const std::string& path,
                                                const Placement& rest) const;
  [[nodiscard]] Joint joint(const json& v, const std::string& path) const;
  // An array of 3 numbers [x, y, z], each within +-limit (`why` names the unit and the rule).
  [[nodiscard]] Eigen::Vector3d vector3(const json& v, const std::string& path, double limit,
                                        std::string_view why) const;
  // An angle in degrees within +-kMaxAngleDeg.
  [[nodiscard]] double angle(const json& v, const std::string& path) const;

  const JsonFieldReader& fields_;
};

// The "parts" object: the definitions, each read once and then copied for every use, and the
// parts being read, to refuse a cycle (scene_parts.cpp).
class PartTable {
 public:
  // `parts` is the document's "parts" object, or null when it has none.
  PartTable(const JsonFieldReader& fields, const json* parts);

  [[nodiscard]] bool defines(const std::string& name) const;
  // "a, b, c", or "none defined".
  [[nodiscard]] std::string names() const;
  // The definition of part `name` (which defines() must accept).
  [[nodiscard]] const json& definition(const std::string& name) const;
  // Every part's name, in the document's order.
  [[nodiscard]] std::vector<std::string> list() const;

  // A part read before: its geometry and the blocks and triangles one use of it adds.
  struct Done {
    SceneObject geometry;
    long long blocks = 0;
    std::size_t triangles = 0;
  };
  // Null for a part not read yet.
  [[nodiscard]] const Done* done(const std::string& name) const;

  // Brackets the reading of part `name`, used at `usePath`: enter() refuses a part that is
  // already being read (a cycle); leave() records the result.
  void enter(const std::string& name, const std::string& usePath);
  void leave(const std::string& name, const SceneObject& geometry, long long blocks,
             std::size_t triangles);

 private:
  const JsonFieldReader& fields_;
  const json* parts_;
  std::map<std::string, Done> done_;
  std::vector<std::string> expanding_;  // parts being read, outermost first
};

// The "objects" array and the tree below each object, expanding parts (scene_objects.cpp).
class ObjectReader {
 public:
  // `maxTriangles` is SceneReadLimits::maxTriangles.
  ObjectReader(const JsonFieldReader& fields, const std::filesystem::path& baseDir,
               const json* parts, std::size_t maxTriangles)
      : fields_(fields),
        triangles_(fields, maxTriangles),
        shapes_(fields, baseDir, triangles_),
        placements_(fields),
        parts_(fields, parts) {}

  // The document's "objects" array at `path`.
  [[nodiscard]] std::vector<SceneObject> objects(const json& list, const std::string& path);
  // Reads the parts no object used, so that a typo in one does not wait for its first use.
  void checkUnusedParts();

 private:
  // A node of an object (a root or a child): geometry or children or a part, placement and
  // motion. `depth` counts the levels above it.
  [[nodiscard]] SceneObject node(const json& v, const std::string& path,
                                 const std::string& defaultName, int depth);
  // The one of "mesh", "shape", "children" and "part" a node must have.
  void requireOneGeometry(const json& v, const std::string& path) const;
  // The mesh, shape or children of a node (or of a part).
  void geometry(const json& v, const std::string& path, int depth, SceneObject& object);
  void children(const json& list, const std::string& path, int depth, SceneObject& object);
  // A part's geometry, read once and copied for every use. `usePath` is where it is used.
  [[nodiscard]] SceneObject part(const std::string& name, const std::string& usePath, int depth);
  void countBlocks(long long more, const std::string& path);

  static constexpr int kMaxDepth = 32;
  static constexpr long long kMaxBlocks = 100000;

  const JsonFieldReader& fields_;
  TriangleBudget triangles_;
  ShapeReader shapes_;
  PlacementReader placements_;
  PartTable parts_;
  long long blocks_ = 0;  // blocks made so far (each use of a part counts)
};

}  // namespace recode::core::detail
