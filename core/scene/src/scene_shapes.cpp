// The block of a leaf: a mesh file or a generated shape (cone, cylinder, capped cone,
// ellipsoid, sphere, box: convex blocks; torus: a closed mesh), validated as what it is.
#include <algorithm>
#include <climits>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/convex_hull.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_error.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/geometry/validate.hpp"

#include "scene_reader.hpp"

namespace recode::core::detail {

namespace {

namespace fs = std::filesystem;
using recode::json::childPath;
using recode::json::describeJsonValue;
using recode::json::jsonText;

struct ShapeSpec {
  std::string_view type;
  std::initializer_list<std::string_view> keys;  // besides "type"
};

// Appended when a mesh file is not a valid convex block: the way out for collision meshes that
// are convex in shape but not clean closed surfaces.
constexpr const char* kHullHint =
    " (to use the convex hull of its vertices instead, give \"hull\": true)";

constexpr std::string_view kShapeTypesText =
    "cone, cylinder, capped_cone, ellipsoid, sphere, box, torus";

const ShapeSpec kShapes[] = {
    {"cone", {"radius", "height", "segments"}},
    {"cylinder", {"radius", "height", "segments"}},
    {"capped_cone", {"radius0", "radius1", "height", "segments", "rings"}},
    {"ellipsoid", {"radii", "segments", "rings"}},
    {"sphere", {"radius", "segments", "rings"}},
    {"box", {"size"}},
    {"torus", {"radius", "tube_radius", "segments", "rings"}},
};

// The one shape that is not convex: generated as a closed mesh.
bool isClosedShape(std::string_view type) {
  return type == "torus";
}

// The size and count fields of one shape object, whose type is known and keys checked.
class ShapeFields {
 public:
  ShapeFields(const JsonFieldReader& fields, const json& v, const std::string& path,
              const std::string& type)
      : fields_(fields), v_(v), path_(path), type_(type) {}

  // A required positive number, at most kMaxCoordinate.
  [[nodiscard]] double size(const char* key) const {
    require(key);
    return fields_.positiveNumberUpTo(v_.at(key), childPath(path_, key), kMaxCoordinate,
                                      "world units");
  }
  // An optional integer of at least `lo`.
  [[nodiscard]] int count(const char* key, int fallback, int lo) const {
    if (!v_.contains(key))
      return fallback;
    return static_cast<int>(fields_.integerInRange(v_.at(key), childPath(path_, key), lo, INT_MAX));
  }
  // A required array of 3 positive numbers, each at most kMaxCoordinate.
  [[nodiscard]] Eigen::Vector3d sizes3(const char* key, const char* what) const {
    require(key);
    const std::string p = childPath(path_, key);
    const json& a = fields_.arrayOfSize(v_.at(key), p, 3, what);
    const auto size = [&](std::size_t i) {
      return fields_.positiveNumberUpTo(a[i], childPath(p, i), kMaxCoordinate, "world units");
    };
    return {size(0), size(1), size(2)};
  }
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    fields_.fail(path, problem);
  }

 private:
  void require(const char* key) const {
    if (!v_.contains(key))
      fields_.fail(path_, std::string("missing key \"") + key + "\" for a " + type_ + " shape");
  }

  const JsonFieldReader& fields_;
  const json& v_;
  const std::string& path_;
  const std::string& type_;
};

// A capped cone's spheres must not contain one another.
TriangleMesh cappedCone(const ShapeFields& f, const json& v, const std::string& path,
                        const TriangleBudget& budget) {
  const double r0 = f.size("radius0");
  const double r1 = f.size("radius1");
  const double height = f.size("height");
  const int segments = f.count("segments", 32, 3);
  const int rings = f.count("rings", 8, 1);
  if (!(height > std::abs(r0 - r1))) {
    f.fail(childPath(path, "height"),
           "must exceed |radius0 - radius1| = " + jsonText(json(std::abs(r0 - r1))) +
               " (otherwise one sphere contains the other), got " + jsonText(v.at("height")));
  }
  budget.check(4.0 * rings * segments, path);
  return makeCappedCone(r0, r1, height, segments, rings);
}

// The mesh of a shape of a known type. The fields are read in the order the messages rely on
// (the first missing or bad one is reported). The triangle counts of generators.hpp are
// checked against the scene's budget before anything is built.
TriangleMesh generate(const ShapeFields& f, const json& v, const std::string& path,
                      const std::string& type, const TriangleBudget& budget) {
  if (type == "cone" || type == "cylinder") {
    const double radius = f.size("radius");
    const double height = f.size("height");
    const int segments = f.count("segments", 32, 3);
    budget.check((type == "cone" ? 2.0 : 4.0) * segments, path);
    return type == "cone" ? makeCone(radius, height, segments)
                          : makeCylinder(radius, height, segments);
  }
  if (type == "capped_cone")
    return cappedCone(f, v, path, budget);
  if (type == "ellipsoid") {
    const Eigen::Vector3d radii = f.sizes3("radii", "3 positive numbers [a, b, c]");
    const int segments = f.count("segments", 32, 3);
    const int rings = f.count("rings", 16, 2);
    budget.check(2.0 * (rings - 1) * segments, path);
    return makeEllipsoid(radii.x(), radii.y(), radii.z(), segments, rings);
  }
  if (type == "sphere") {
    const double radius = f.size("radius");
    const int segments = f.count("segments", 32, 3);
    const int rings = f.count("rings", 16, 2);
    budget.check(2.0 * (rings - 1) * segments, path);
    return makeSphere(radius, segments, rings);
  }
  if (type == "torus") {
    const double radius = f.size("radius");
    const double tube = f.size("tube_radius");
    if (!(tube < radius))
      f.fail(childPath(path, "tube_radius"), "must be below radius (" + jsonText(v.at("radius")) +
                                                 ") so that the hole stays open, "
                                                 "got " +
                                                 jsonText(v.at("tube_radius")));
    const int segments = f.count("segments", 32, 3);
    const int rings = f.count("rings", 16, 3);
    budget.check(2.0 * segments * rings, path);
    return makeTorus(radius, tube, segments, rings);
  }
  const Eigen::Vector3d full = f.sizes3("size", "3 positive numbers [sx, sy, sz]");
  return makeBox(full / 2.0);
}

}  // namespace

LeafMesh ShapeReader::leafMesh(const json& v, const std::string& path) const {
  const auto flag = [&v](const char* key) { return v.contains(key) && v.at(key).get<bool>(); };
  if (v.contains("mesh")) {
    const MeshUse use = flag("hull")     ? MeshUse::Hull
                        : flag("closed") ? MeshUse::Closed
                                         : MeshUse::ConvexBlock;
    return {meshFile(v.at("mesh"), childPath(path, "mesh"), use), use == MeshUse::Closed};
  }
  const std::string p = childPath(path, "shape");
  std::string type;
  TriangleMesh mesh = shape(v.at("shape"), p, &type);
  const bool closed = isClosedShape(type);
  try {
    if (closed)
      validateClosedMesh(mesh, "the generated " + type);
    else
      validateConvexBlock(mesh, "the generated " + type);
  } catch (const MeshError& e) {
    fields_.fail(p, e.what());
  }
  return {std::move(mesh), closed};
}

bool ShapeReader::checkMeshOptions(const json& v, const std::string& path) const {
  bool groups = false;
  for (const char* key : {"hull", "parts_from_groups", "closed"}) {
    if (!v.contains(key))
      continue;
    const std::string p = childPath(path, key);
    if (!v.contains("mesh"))
      fields_.fail(p, std::string("\"") + key + "\" applies to a \"mesh\" only");
    if (!v.at(key).is_boolean())
      fields_.fail(p, "expected true or false, got " + describeJsonValue(v.at(key)));
    if (std::string_view(key) == "parts_from_groups")
      groups = v.at(key).get<bool>();
  }
  const auto on = [&v](const char* key) { return v.contains(key) && v.at(key).get<bool>(); };
  if (on("closed") && (on("hull") || on("parts_from_groups")))
    fields_.fail(childPath(path, "closed"),
                 "a closed mesh is the file's faces as one surface: give \"closed\": true "
                 "without \"hull\" or \"parts_from_groups\"");
  return groups;
}

// Relative to the scene file's directory; the mesh reader's and validator's messages are kept.
TriangleMesh ShapeReader::meshFile(const json& v, const std::string& path, MeshUse use) const {
  const fs::path file = baseDir_ / fs::path(fields_.nonEmptyString(v, path));
  TriangleMesh mesh;
  try {
    mesh = readMesh(file);
  } catch (const MeshError& e) {
    fields_.fail(path, e.what());
  }
  return meshBlock(std::move(mesh), file.string(), path, use);
}

std::vector<std::pair<std::string, TriangleMesh>> ShapeReader::meshGroups(
    const json& v, const std::string& path) const {
  const bool hull = v.contains("hull") && v.at("hull").get<bool>();
  const std::string p = childPath(path, "mesh");
  const fs::path file = baseDir_ / fs::path(fields_.nonEmptyString(v.at("mesh"), p));
  std::vector<MeshGroup> groups;
  try {
    groups = readObjGroups(file);
  } catch (const MeshError& e) {
    fields_.fail(p, e.what());
  }
  std::vector<std::pair<std::string, TriangleMesh>> blocks;
  for (MeshGroup& group : groups) {
    TriangleMesh block =
        meshBlock(std::move(group.mesh), file.string() + ": group '" + group.name + "'", p,
                  hull ? MeshUse::Hull : MeshUse::ConvexBlock);
    blocks.emplace_back(group.name, std::move(block));
  }
  return blocks;
}

// Vertices are held to the scene's coordinate range before validation, whose tolerances
// overflow for coordinates near 1e300 ("height ... is -nan (tolerance inf)").
TriangleMesh ShapeReader::meshBlock(TriangleMesh mesh, const std::string& what,
                                    const std::string& path, MeshUse use) const {
  triangles_.take(mesh.triangles.size(), path);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& p = mesh.vertices[i];
    if (p.cwiseAbs().maxCoeff() > kMaxCoordinate) {
      using recode::json::shortNumber;
      fields_.fail(path, what + ": vertex " + std::to_string(i) + " (" + shortNumber(p.x()) + ", " +
                             shortNumber(p.y()) + ", " + shortNumber(p.z()) +
                             ") has a coordinate outside -1e+09..1e+09 (world units)");
    }
  }
  if (use == MeshUse::Hull) {
    try {
      return convexHullBlock(mesh.vertices, what);
    } catch (const MeshError& e) {
      fields_.fail(path, e.what());
    }
  }
  if (use == MeshUse::Closed) {
    try {
      validateClosedMesh(mesh, what);
    } catch (const MeshError& e) {
      fields_.fail(path, e.what());
    }
    return mesh;
  }
  try {
    validateConvexBlock(mesh, what);
  } catch (const MeshError& e) {
    fields_.fail(path, std::string(e.what()) + kHullHint);
  }
  return mesh;
}

TriangleMesh ShapeReader::shape(const json& v, const std::string& path,
                                std::string* typeName) const {
  fields_.requireObject(v, path);
  const std::string type = shapeType(v, path);
  *typeName = type;
  try {
    TriangleMesh mesh = generate(ShapeFields(fields_, v, path, type), v, path, type, triangles_);
    triangles_.take(mesh.triangles.size(), path);
    return mesh;
  } catch (const std::invalid_argument& e) {
    fields_.fail(path, e.what());
  }
}

std::string ShapeReader::shapeType(const json& v, const std::string& path) const {
  if (!v.contains("type"))
    fields_.fail(path, "missing key \"type\" (one of " + std::string(kShapeTypesText) + ")");
  const std::string typePath = childPath(path, "type");
  const json& t = v.at("type");
  if (!t.is_string()) {
    fields_.fail(typePath, "expected a shape type (" + std::string(kShapeTypesText) + "), got " +
                               describeJsonValue(t));
  }
  const std::string type = t.get<std::string>();
  const auto spec = std::find_if(std::begin(kShapes), std::end(kShapes),
                                 [&](const ShapeSpec& s) { return s.type == type; });
  if (spec == std::end(kShapes)) {
    fields_.fail(typePath, "unknown shape type " + jsonText(t) + " (expected one of " +
                               std::string(kShapeTypesText) + ")");
  }
  for (const auto& [key, value] : v.items()) {
    if (key == "type" || std::find(spec->keys.begin(), spec->keys.end(), key) != spec->keys.end())
      continue;
    std::string list = "type";
    for (std::string_view k : spec->keys)
      list += ", " + std::string(k);
    fields_.fail(childPath(path, key),
                 "unknown key for a " + type + " shape (allowed: " + list + ")");
  }
  return type;
}

}  // namespace recode::core::detail
