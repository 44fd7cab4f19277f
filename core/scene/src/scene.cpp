// Scene files: the scene schema (view, objects, shapes, motion) read from a JSON document.
#include "recode/scene/scene.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <initializer_list>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_error.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/geometry/validate.hpp"
#include "recode/json/document.hpp"

namespace recode::core {

namespace {

using nlohmann::json;
using recode::json::childPath;
using recode::json::describeJsonValue;
using recode::json::JsonFieldReader;
using recode::json::jsonText;
using recode::json::parseJsonDocument;
namespace fs = std::filesystem;

struct ShapeSpec {
  std::string_view type;
  std::initializer_list<std::string_view> keys;  // besides "type"
};

constexpr std::string_view kShapeTypesText = "cone, cylinder, capped_cone, ellipsoid, sphere, box";

// Walks the document; every error names the JSON path of the value it is about.
class SceneReader {
 public:
  SceneReader(const std::string& sourceName, const fs::path& baseDir)
      : fields_(sourceName), baseDir_(baseDir) {}

  Scene scene(const json& doc) {
    Scene scene;
    scene.sourceName = fields_.sourceName();
    fields_.requireObject(doc, "");
    fields_.requireOnlyKeys(doc, "", {"view", "objects", "frames", "parts"});
    if (doc.contains("view"))
      scene.view = view(doc.at("view"), "view");
    if (doc.contains("frames"))
      scene.frames =
          static_cast<int>(fields_.integerInRange(doc.at("frames"), "frames", 1, INT_MAX));
    if (doc.contains("parts")) {
      parts_ = &doc.at("parts");
      if (!parts_->is_object())
        fields_.fail("parts",
                     "expected an object of named parts, got " + describeJsonValue(*parts_));
    }
    if (!doc.contains("objects"))
      fields_.fail("", "missing key \"objects\" (the list of objects)");
    const json& objects = doc.at("objects");
    if (!objects.is_array())
      fields_.fail("objects", "expected an array of objects, got " + describeJsonValue(objects));
    if (objects.empty())
      fields_.fail("objects", "expected at least one object, got an empty array");
    for (std::size_t i = 0; i < objects.size(); ++i) {
      scene.objects.push_back(
          node(objects[i], childPath("objects", i), "object " + std::to_string(i), 0));
    }
    // Parts nobody uses are still checked: a typo in one should not wait for its first use.
    if (parts_) {
      for (const auto& [name, value] : parts_->items())
        if (!partCache_.contains(name))
          (void)part(name, childPath("parts", name), 0);
    }
    return scene;
  }

 private:
  ViewSpec view(const json& v, const std::string& path) const {
    fields_.requireObject(v, path);
    fields_.requireOnlyKeys(v, path, {"axis", "window", "resolution", "pixel_size"});
    ViewSpec spec;
    if (v.contains("axis")) {
      const std::string p = childPath(path, "axis");
      const json& a = v.at("axis");
      if (!a.is_string())
        fields_.fail(p, "expected \"x\", \"y\" or \"z\", got " + describeJsonValue(a));
      const std::optional<ViewAxis> axis = parseViewAxis(a.get<std::string>());
      if (!axis)
        fields_.fail(p, "expected \"x\", \"y\" or \"z\", got " + jsonText(a));
      spec.axis = *axis;
    }
    if (v.contains("window")) {
      const std::string p = childPath(path, "window");
      const json& w =
          fields_.arrayOfSize(v.at("window"), p, 4, "4 numbers [umin, vmin, umax, vmax]");
      ViewWindow window;
      window.umin = fields_.finiteNumber(w[0], childPath(p, 0));
      window.vmin = fields_.finiteNumber(w[1], childPath(p, 1));
      window.umax = fields_.finiteNumber(w[2], childPath(p, 2));
      window.vmax = fields_.finiteNumber(w[3], childPath(p, 3));
      if (!(window.umin < window.umax)) {
        fields_.fail(
            p, "umin (" + jsonText(w[0]) + ") must be less than umax (" + jsonText(w[2]) + ")");
      }
      if (!(window.vmin < window.vmax)) {
        fields_.fail(
            p, "vmin (" + jsonText(w[1]) + ") must be less than vmax (" + jsonText(w[3]) + ")");
      }
      if (!std::isfinite(window.umax - window.umin) || !std::isfinite(window.vmax - window.vmin))
        fields_.fail(p, "the window's width or height overflows a double");
      spec.window = window;
    }
    if (v.contains("resolution")) {
      const std::string p = childPath(path, "resolution");
      const json& r = fields_.arrayOfSize(v.at("resolution"), p, 2, "2 integers [W, H]");
      spec.resolution = std::array<int, 2>{
          static_cast<int>(fields_.integerInRange(r[0], childPath(p, 0), 1, 16384)),
          static_cast<int>(fields_.integerInRange(r[1], childPath(p, 1), 1, 16384))};
    }
    if (v.contains("pixel_size")) {
      const std::string p = childPath(path, "pixel_size");
      if (spec.resolution)
        fields_.fail(p, "cannot be given together with \"resolution\" (give one of the two)");
      spec.pixelSize = fields_.positiveNumber(v.at("pixel_size"), p);
    }
    return spec;
  }

  // A node of an object (a root or a child): geometry or children or a part, placement and
  // motion. `depth` counts the levels above it.
  SceneObject node(const json& v, const std::string& path, const std::string& defaultName,
                   int depth) {
    fields_.requireObject(v, path);
    fields_.requireOnlyKeys(v, path,
                            {"name", "mesh", "shape", "children", "part", "position",
                             "rotation_deg", "motion", "keyframes", "joint"});
    if (depth > kMaxDepth)
      fields_.fail(path, "objects nested more than " + std::to_string(kMaxDepth) + " levels deep");
    std::string given;
    int count = 0;
    for (const char* key : {"mesh", "shape", "children", "part"}) {
      if (!v.contains(key))
        continue;
      given += std::string(count++ ? " and \"" : "\"") + key + "\"";
    }
    if (count > 1) {
      fields_.fail(
          path, "give exactly one of \"mesh\", \"shape\", \"children\" and \"part\", got " + given);
    }
    if (count == 0) {
      fields_.fail(path,
                   "missing \"mesh\", \"shape\", \"children\" or \"part\" (give exactly one)");
    }

    SceneObject object;
    if (v.contains("part")) {
      const std::string p = childPath(path, "part");
      const std::string name = fields_.nonEmptyString(v.at("part"), p);
      if (!parts_ || !parts_->contains(name)) {
        fields_.fail(p, "no part named " + jsonText(json(name)) + " (parts: " + partNames() + ")");
      }
      object = part(name, p, depth);
    } else {
      geometry(v, path, depth, object);
    }
    object.jsonPath = path;
    object.name = v.contains("name") ? fields_.nonEmptyString(v.at("name"), childPath(path, "name"))
                                     : defaultName;
    placement(v, path, object);
    return object;
  }

  // The mesh, shape or children of a node (or of a part).
  void geometry(const json& v, const std::string& path, int depth, SceneObject& object) {
    if (v.contains("children")) {
      const std::string p = childPath(path, "children");
      const json& list = v.at("children");
      if (!list.is_array())
        fields_.fail(p, "expected an array of objects, got " + describeJsonValue(list));
      if (list.empty())
        fields_.fail(p, "expected at least one child, got an empty array");
      std::map<std::string, std::size_t> seen;
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string cp = childPath(p, i);
        object.children.push_back(node(list[i], cp, "child " + std::to_string(i), depth + 1));
        const std::string& name = object.children.back().name;
        const auto [it, added] = seen.emplace(name, i);
        if (!added) {
          fields_.fail(cp, "duplicate name " + jsonText(json(name)) + " (also " +
                               childPath(p, it->second) +
                               "); children of one object need distinct names, so that every "
                               "block has its own path");
        }
      }
      return;
    }
    countBlocks(1, path);
    if (v.contains("mesh")) {
      const std::string p = childPath(path, "mesh");
      const fs::path file = baseDir_ / fs::path(fields_.nonEmptyString(v.at("mesh"), p));
      try {
        object.localMesh = readMesh(file);
        validateConvexBlock(object.localMesh, file.string());
      } catch (const MeshError& e) {
        fields_.fail(p, e.what());
      }
    } else {
      const std::string p = childPath(path, "shape");
      std::string type;
      object.localMesh = shape(v.at("shape"), p, &type);
      try {
        validateConvexBlock(object.localMesh, "the generated " + type);
      } catch (const MeshError& e) {
        fields_.fail(p, e.what());
      }
    }
  }

  // A part's geometry, read once and copied for every use. `usePath` is where it is used,
  // for the message when a part uses itself.
  SceneObject part(const std::string& name, const std::string& usePath, int depth) {
    if (const auto done = partCache_.find(name); done != partCache_.end()) {
      countBlocks(partBlocks_.at(name), usePath);
      return done->second;
    }
    const auto open = std::find(expanding_.begin(), expanding_.end(), name);
    if (open != expanding_.end()) {
      std::string cycle;
      for (auto it = open; it != expanding_.end(); ++it)
        cycle += *it + " -> ";
      fields_.fail(usePath, "part " + jsonText(json(name)) + " contains itself (" + cycle + name +
                                "); parts must not form a cycle");
    }
    const std::string path = childPath("parts", name);
    const json& v = parts_->at(name);
    fields_.requireObject(v, path);
    fields_.requireOnlyKeys(v, path, {"mesh", "shape", "children"},
                            " for a part (a part is geometry only; place it where it is used)");
    const int given = static_cast<int>(v.contains("mesh")) + static_cast<int>(v.contains("shape")) +
                      static_cast<int>(v.contains("children"));
    if (given != 1)
      fields_.fail(path, "give exactly one of \"mesh\", \"shape\" and \"children\"");
    expanding_.push_back(name);
    const long long before = blocks_;
    SceneObject geometryOnly;
    geometry(v, path, depth, geometryOnly);
    expanding_.pop_back();
    partCache_.emplace(name, geometryOnly);
    partBlocks_.emplace(name, blocks_ - before);
    return geometryOnly;
  }

  void countBlocks(long long more, const std::string& path) {
    blocks_ += more;
    if (blocks_ > kMaxBlocks) {
      fields_.fail(path, "more than " + std::to_string(kMaxBlocks) +
                             " blocks in the scene (parts used inside parts multiply)");
    }
  }

  std::string partNames() const {
    std::string names;
    if (parts_) {
      for (const auto& [name, value] : parts_->items())
        names += (names.empty() ? "" : ", ") + name;
    }
    return names.empty() ? "none defined" : names;
  }

  // position, rotation_deg, motion, keyframes, joint.
  void placement(const json& v, const std::string& path, SceneObject& object) const {
    if (v.contains("position"))
      object.position = vector3(v.at("position"), childPath(path, "position"));
    if (v.contains("rotation_deg"))
      object.rotationDeg = vector3(v.at("rotation_deg"), childPath(path, "rotation_deg"));
    if (v.contains("motion") && v.contains("keyframes"))
      fields_.fail(path, "give at most one of \"motion\" and \"keyframes\"");
    if (v.contains("motion"))
      object.motion = motion(v.at("motion"), childPath(path, "motion"), object.position);
    if (v.contains("keyframes"))
      object.keyframes = keyframes(v.at("keyframes"), childPath(path, "keyframes"), object);
    if (v.contains("joint"))
      object.joint = joint(v.at("joint"), childPath(path, "joint"));
  }

  Motion motion(const json& v, const std::string& path, const Eigen::Vector3d& position) const {
    fields_.requireObject(v, path);
    fields_.requireOnlyKeys(v, path, {"velocity", "angular_velocity_deg", "bounce_within"});
    Motion m;
    if (v.contains("velocity"))
      m.velocity = vector3(v.at("velocity"), childPath(path, "velocity"));
    if (v.contains("angular_velocity_deg")) {
      m.angularVelocityDeg =
          vector3(v.at("angular_velocity_deg"), childPath(path, "angular_velocity_deg"));
    }
    if (v.contains("bounce_within")) {
      const std::string p = childPath(path, "bounce_within");
      const json& box = fields_.arrayOfSize(v.at("bounce_within"), p, 2,
                                            "2 corners [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
      Aabb bounds;
      bounds.min = vector3(box[0], childPath(p, 0));
      bounds.max = vector3(box[1], childPath(p, 1));
      for (int i = 0; i < 3; ++i) {
        if (!(bounds.min[i] <= bounds.max[i])) {
          fields_.fail(p, "the first corner must not exceed the second (" +
                              jsonText(box[0][static_cast<std::size_t>(i)]) + " > " +
                              jsonText(box[1][static_cast<std::size_t>(i)]) + " along " + "xyz"[i] +
                              ")");
        }
        if (!(bounds.min[i] <= position[i] && position[i] <= bounds.max[i])) {
          fields_.fail(p, "the object's position " + jsonText(json(position[i])) + " along " +
                              "xyz"[i] + " lies outside the box");
        }
      }
      m.bounceWithin = bounds;
    }
    return m;
  }

  std::vector<Keyframe> keyframes(const json& v, const std::string& path,
                                  const SceneObject& object) const {
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
      key.frame = static_cast<int>(
          fields_.integerInRange(k.at("frame"), childPath(p, "frame"), 0, INT_MAX));
      if (!keys.empty() && key.frame <= keys.back().frame) {
        fields_.fail(childPath(p, "frame"), "keyframes must be in increasing frame order; got " +
                                                std::to_string(key.frame) + " after " +
                                                std::to_string(keys.back().frame));
      }
      key.position = k.contains("position") ? vector3(k.at("position"), childPath(p, "position"))
                                            : object.position;
      key.rotationDeg = k.contains("rotation_deg")
                            ? vector3(k.at("rotation_deg"), childPath(p, "rotation_deg"))
                            : object.rotationDeg;
      keys.push_back(key);
    }
    return keys;
  }

  Joint joint(const json& v, const std::string& path) const {
    fields_.requireObject(v, path);
    fields_.requireOnlyKeys(v, path, {"axis", "angle_deg", "rate_deg", "min_deg", "max_deg"});
    if (!v.contains("axis"))
      fields_.fail(path, "missing key \"axis\" (the hinge direction [x, y, z])");
    Joint j;
    const std::string axisPath = childPath(path, "axis");
    const Eigen::Vector3d axis = vector3(v.at("axis"), axisPath);
    const double length = axis.norm();
    if (!(length > 0.0) || !std::isfinite(length))
      fields_.fail(axisPath, "expected a non-zero direction, got " + jsonText(v.at("axis")));
    j.axis = axis / length;
    if (v.contains("angle_deg"))
      j.angleDeg = fields_.finiteNumber(v.at("angle_deg"), childPath(path, "angle_deg"));
    if (v.contains("rate_deg"))
      j.rateDeg = fields_.finiteNumber(v.at("rate_deg"), childPath(path, "rate_deg"));
    if (v.contains("min_deg"))
      j.minDeg = fields_.finiteNumber(v.at("min_deg"), childPath(path, "min_deg"));
    if (v.contains("max_deg"))
      j.maxDeg = fields_.finiteNumber(v.at("max_deg"), childPath(path, "max_deg"));
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

  // An array of 3 finite numbers [x, y, z].
  Eigen::Vector3d vector3(const json& value, const std::string& path) const {
    fields_.arrayOfSize(value, path, 3, "3 numbers [x, y, z]");
    return {fields_.finiteNumber(value[0], childPath(path, 0)),
            fields_.finiteNumber(value[1], childPath(path, 1)),
            fields_.finiteNumber(value[2], childPath(path, 2))};
  }

  // The shape's mesh; *typeName is set to its "type".
  TriangleMesh shape(const json& v, const std::string& path, std::string* typeName) const {
    static const ShapeSpec kShapes[] = {
        {"cone", {"radius", "height", "segments"}},
        {"cylinder", {"radius", "height", "segments"}},
        {"capped_cone", {"radius0", "radius1", "height", "segments", "rings"}},
        {"ellipsoid", {"radii", "segments", "rings"}},
        {"sphere", {"radius", "segments", "rings"}},
        {"box", {"size"}},
    };
    fields_.requireObject(v, path);
    if (!v.contains("type"))
      fields_.fail(path, "missing key \"type\" (one of " + std::string(kShapeTypesText) + ")");
    const std::string typePath = childPath(path, "type");
    const json& t = v.at("type");
    if (!t.is_string()) {
      fields_.fail(typePath, "expected a shape type (" + std::string(kShapeTypesText) + "), got " +
                                 describeJsonValue(t));
    }
    const std::string type = t.get<std::string>();
    *typeName = type;
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

    const auto size = [&](const char* key) -> double {
      const std::string p = childPath(path, key);
      if (!v.contains(key))
        fields_.fail(path, std::string("missing key \"") + key + "\" for a " + type + " shape");
      return fields_.positiveNumber(v.at(key), p);
    };
    const auto count = [&](const char* key, int fallback, int lo) -> int {
      if (!v.contains(key))
        return fallback;
      return static_cast<int>(fields_.integerInRange(v.at(key), childPath(path, key), lo, INT_MAX));
    };
    const auto sizes3 = [&](const char* key, const char* what) -> Eigen::Vector3d {
      const std::string p = childPath(path, key);
      if (!v.contains(key))
        fields_.fail(path, std::string("missing key \"") + key + "\" for a " + type + " shape");
      const json& a = fields_.arrayOfSize(v.at(key), p, 3, what);
      return {fields_.positiveNumber(a[0], childPath(p, 0)),
              fields_.positiveNumber(a[1], childPath(p, 1)),
              fields_.positiveNumber(a[2], childPath(p, 2))};
    };

    try {
      if (type == "cone" || type == "cylinder") {
        const double radius = size("radius");
        const double height = size("height");
        const int segments = count("segments", 32, 3);
        return type == "cone" ? makeCone(radius, height, segments)
                              : makeCylinder(radius, height, segments);
      }
      if (type == "capped_cone") {
        const double r0 = size("radius0");
        const double r1 = size("radius1");
        const double height = size("height");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 8, 1);
        if (!(height > std::abs(r0 - r1))) {
          fields_.fail(childPath(path, "height"),
                       "must exceed |radius0 - radius1| = " + jsonText(json(std::abs(r0 - r1))) +
                           " (otherwise one sphere contains the other), got " +
                           jsonText(v.at("height")));
        }
        return makeCappedCone(r0, r1, height, segments, rings);
      }
      if (type == "ellipsoid") {
        const Eigen::Vector3d radii = sizes3("radii", "3 positive numbers [a, b, c]");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 16, 2);
        return makeEllipsoid(radii.x(), radii.y(), radii.z(), segments, rings);
      }
      if (type == "sphere") {
        const double radius = size("radius");
        const int segments = count("segments", 32, 3);
        const int rings = count("rings", 16, 2);
        return makeSphere(radius, segments, rings);
      }
      const Eigen::Vector3d full = sizes3("size", "3 positive numbers [sx, sy, sz]");
      return makeBox(full / 2.0);
    } catch (const std::invalid_argument& e) {
      fields_.fail(path, e.what());
    }
  }

  static constexpr int kMaxDepth = 32;
  static constexpr long long kMaxBlocks = 100000;

  JsonFieldReader fields_;
  fs::path baseDir_;
  const json* parts_ = nullptr;
  std::map<std::string, SceneObject> partCache_;
  std::vector<std::string> expanding_;           // parts being read, outermost first
  std::map<std::string, long long> partBlocks_;  // blocks in one use of each part
  long long blocks_ = 0;                         // blocks made so far (each use of a part counts)
};

}  // namespace

TriangleMesh SceneObject::worldMesh() const {
  return transformed(localMesh, pose());
}

// The JSON reading layer throws its own error; callers catch SceneError, whose message it
// keeps byte for byte.
Scene parseScene(std::string_view jsonText, const std::string& sourceName,
                 const std::filesystem::path& baseDir) {
  try {
    const json doc = parseJsonDocument(jsonText, sourceName);
    return SceneReader(sourceName, baseDir).scene(doc);
  } catch (const SceneError&) {
    throw;
  } catch (const recode::json::JsonError& e) {
    throw SceneError(e);
  }
}

Scene loadScene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec))
    throw SceneError(name, "", "cannot open scene file (file not found)");
  if (fs::is_directory(file, ec))
    throw SceneError(name, "", "cannot open scene file (it is a directory)");
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw SceneError(name, "", "cannot open scene file (not readable)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw SceneError(name, "", "error while reading the scene file");
  return parseScene(text.str(), name, file.parent_path());
}

}  // namespace recode::core
