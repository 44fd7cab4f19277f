// The objects of a scene file and the tree below each: nodes, children, parts in use.
#include <map>
#include <string>
#include <vector>

#include "scene_reader.hpp"

namespace recode::core::detail {

using recode::json::childPath;
using recode::json::describeJsonValue;
using recode::json::jsonText;

std::vector<SceneObject> ObjectReader::objects(const json& list, const std::string& path) {
  if (!list.is_array())
    fields_.fail(path, "expected an array of objects, got " + describeJsonValue(list));
  if (list.empty())
    fields_.fail(path, "expected at least one object, got an empty array");
  std::vector<SceneObject> roots;
  for (std::size_t i = 0; i < list.size(); ++i)
    roots.push_back(node(list[i], childPath(path, i), "object " + std::to_string(i), 0));
  return roots;
}

void ObjectReader::checkUnusedParts() {
  for (const std::string& name : parts_.list()) {
    if (!parts_.done(name))
      (void)part(name, childPath("parts", name), 0);
  }
}

SceneObject ObjectReader::node(const json& v, const std::string& path,
                               const std::string& defaultName, int depth) {
  fields_.requireObject(v, path);
  fields_.requireOnlyKeys(
      v, path,
      {"name", "mesh", "hull", "parts_from_groups", "closed", "shape", "children", "part",
       "position", "rotation_deg", "motion", "keyframes", "joint"});
  if (depth > kMaxDepth)
    fields_.fail(path, "objects nested more than " + std::to_string(kMaxDepth) + " levels deep");
  requireOneGeometry(v, path);

  (void)shapes_.checkMeshOptions(v, path);  // "hull" next to "part" is refused, not ignored
  SceneObject object;
  if (v.contains("part")) {
    const std::string p = childPath(path, "part");
    const std::string name = fields_.nonEmptyString(v.at("part"), p);
    if (!parts_.defines(name))
      fields_.fail(p, "no part named " + jsonText(json(name)) + " (parts: " + parts_.names() + ")");
    object = part(name, p, depth);
  } else {
    geometry(v, path, depth, object);
  }
  object.jsonPath = path;
  object.name = v.contains("name") ? fields_.nonEmptyString(v.at("name"), childPath(path, "name"))
                                   : defaultName;
  placements_.read(v, path, object);
  return object;
}

void ObjectReader::requireOneGeometry(const json& v, const std::string& path) const {
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
  if (count == 0)
    fields_.fail(path, "missing \"mesh\", \"shape\", \"children\" or \"part\" (give exactly one)");
}

void ObjectReader::geometry(const json& v, const std::string& path, int depth,
                            SceneObject& object) {
  const bool fromGroups = shapes_.checkMeshOptions(v, path);
  if (v.contains("children")) {
    children(v.at("children"), childPath(path, "children"), depth, object);
    return;
  }
  if (fromGroups) {
    // One child block per OBJ object or group, at the node's own frame.
    for (auto& [name, mesh] : shapes_.meshGroups(v, path)) {
      countBlocks(1, path);
      SceneObject leaf;
      leaf.name = name;
      leaf.jsonPath = childPath(childPath(path, "mesh"), name);
      leaf.localMesh = std::move(mesh);
      object.children.push_back(std::move(leaf));
    }
    return;
  }
  countBlocks(1, path);
  LeafMesh leaf = shapes_.leafMesh(v, path);
  object.localMesh = std::move(leaf.mesh);
  object.closed = leaf.closed;
}

// Children of one node need distinct names, so that every block has its own path.
void ObjectReader::children(const json& list, const std::string& path, int depth,
                            SceneObject& object) {
  if (!list.is_array())
    fields_.fail(path, "expected an array of objects, got " + describeJsonValue(list));
  if (list.empty())
    fields_.fail(path, "expected at least one child, got an empty array");
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string cp = childPath(path, i);
    object.children.push_back(node(list[i], cp, "child " + std::to_string(i), depth + 1));
    const std::string& name = object.children.back().name;
    const auto [it, added] = seen.emplace(name, i);
    if (!added) {
      fields_.fail(cp, "duplicate name " + jsonText(json(name)) + " (also " +
                           childPath(path, it->second) +
                           "); children of one object need distinct names, so that every "
                           "block has its own path");
    }
  }
}

SceneObject ObjectReader::part(const std::string& name, const std::string& usePath, int depth) {
  if (const PartTable::Done* done = parts_.done(name)) {
    countBlocks(done->blocks, usePath);
    triangles_.take(done->triangles, usePath);
    return done->geometry;
  }
  parts_.enter(name, usePath);
  const std::string path = childPath("parts", name);
  const json& v = parts_.definition(name);
  fields_.requireObject(v, path);
  fields_.requireOnlyKeys(v, path,
                          {"mesh", "hull", "parts_from_groups", "closed", "shape", "children"},
                          " for a part (a part is geometry only; place it where it is used)");
  const int given = static_cast<int>(v.contains("mesh")) + static_cast<int>(v.contains("shape")) +
                    static_cast<int>(v.contains("children"));
  if (given != 1)
    fields_.fail(path, "give exactly one of \"mesh\", \"shape\" and \"children\"");
  const long long before = blocks_;
  const std::size_t trianglesBefore = triangles_.used();
  SceneObject geometryOnly;
  geometry(v, path, depth, geometryOnly);
  parts_.leave(name, geometryOnly, blocks_ - before, triangles_.used() - trianglesBefore);
  return geometryOnly;
}

// Parts used inside parts multiply, so a small file can describe a huge scene.
void ObjectReader::countBlocks(long long more, const std::string& path) {
  blocks_ += more;
  if (blocks_ > kMaxBlocks) {
    fields_.fail(path, "more than " + std::to_string(kMaxBlocks) +
                           " blocks in the scene (parts used inside parts multiply)");
  }
}

void TriangleBudget::check(double triangles, const std::string& path) const {
  const double total = static_cast<double>(used_) + triangles;
  if (total > static_cast<double>(limit_)) {
    // Whole counts print as integers; a count from huge shape parameters, in short form.
    const std::string count = total < 1e15 ? std::to_string(static_cast<long long>(total))
                                           : recode::json::shortNumber(total);
    fields_.fail(path, "this block would bring the scene to " + count +
                           " triangles, over the limit of " + std::to_string(limit_) +
                           " triangles in a scene (each use of a part counts again)");
  }
}

void TriangleBudget::take(std::size_t triangles, const std::string& path) {
  check(static_cast<double>(triangles), path);
  used_ += triangles;
}

}  // namespace recode::core::detail
