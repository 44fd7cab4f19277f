// Scene files: the top level of the schema (view, frames, parts, objects), read from a JSON
// document by the section readers of scene_reader.hpp.
#include "recode/scene/scene.hpp"

#include <string>

#include "recode/io/bounded_read.hpp"
#include "scene_reader.hpp"

namespace recode::core {

namespace {

namespace fs = std::filesystem;
using detail::json;
using detail::JsonFieldReader;

// Every error names the JSON path of the value it is about.
Scene readScene(const json& doc, const std::string& sourceName, const fs::path& baseDir,
                const SceneReadLimits& limits) {
  const JsonFieldReader fields(sourceName);
  Scene scene;
  scene.sourceName = sourceName;
  fields.requireObject(doc, "");
  fields.requireOnlyKeys(doc, "", {"view", "objects", "frames", "parts"});
  if (doc.contains("view"))
    scene.view = detail::readView(fields, doc.at("view"), "view");
  if (doc.contains("frames"))
    scene.frames =
        static_cast<int>(fields.integerInRange(doc.at("frames"), "frames", 1, kMaxFrames));
  detail::ObjectReader objects(fields, baseDir, doc.contains("parts") ? &doc.at("parts") : nullptr,
                               limits.maxTriangles);
  if (!doc.contains("objects"))
    fields.fail("", "missing key \"objects\" (the list of objects)");
  scene.objects = objects.objects(doc.at("objects"), "objects");
  objects.checkUnusedParts();
  return scene;
}

}  // namespace

TriangleMesh SceneObject::worldMesh() const {
  return transformed(localMesh, pose());
}

// The JSON reading layer throws its own error; callers catch SceneError, whose message it
// keeps byte for byte.
Scene parseScene(std::string_view jsonText, const std::string& sourceName,
                 const std::filesystem::path& baseDir, const SceneReadLimits& limits) {
  try {
    return readScene(recode::json::parseJsonDocument(jsonText, sourceName), sourceName, baseDir,
                     limits);
  } catch (const SceneError&) {
    throw;
  } catch (const recode::json::JsonError& e) {
    throw SceneError(e);
  }
}

Scene loadScene(const std::filesystem::path& file, const SceneReadLimits& limits) {
  std::string text;
  try {
    text = recode::io::readBoundedFile(file, recode::io::kMaxJsonFileBytes, "scene file");
  } catch (const recode::io::FileReadError& e) {
    throw SceneError(e.file(), "", e.problem());
  }
  return parseScene(text, file.string(), file.parent_path(), limits);
}

namespace {

const SceneObject* firstClosedLeaf(const std::vector<SceneObject>& nodes) {
  for (const SceneObject& node : nodes) {
    if (node.isLeaf() && node.closed)
      return &node;
    if (const SceneObject* found = firstClosedLeaf(node.children))
      return found;
  }
  return nullptr;
}

}  // namespace

void requireConvexBlocks(const Scene& scene, std::string_view who) {
  if (const SceneObject* leaf = firstClosedLeaf(scene.objects))
    throw SceneError(scene.sourceName, leaf->jsonPath,
                     "a closed mesh (\"closed\": true or a torus) is decided by `recode pair` "
                     "alone; " +
                         std::string(who) + " takes convex blocks");
}

}  // namespace recode::core
