// Writes every built-in experiment scene (`recode run --list`) as the batch tests read it
// (test_batches.py): each leaf block's mesh in its own coordinates, the object it belongs to, and
// its world pose (local -> world, 4 x 4 row-major) at every frame of the scene, as `recode run`
// poses it. nlohmann::json writes each double in the shortest form that reads back to the same
// bits, so Python reads back the same bits.
//
// Each scene is tessellated at its default triangles per block, or at most MAX_TRIANGLES (128:
// hierarchy-9's 2,880 would only slow the tests).
//
//   recode_python_scene_frames OUT.json [MAX_TRIANGLES_PER_BLOCK]
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/hierarchy.hpp"

namespace {

using namespace recode;
using Json = nlohmann::json;

Json sceneJson(const core::BuiltinSceneInfo& info, int trianglesPerBlock) {
  const core::Scene scene = core::builtinExperimentScene(info.name, trianglesPerBlock);
  std::vector<core::ObjectTree> trees;
  for (const core::SceneObject& object : scene.objects)
    trees.emplace_back(object);
  Json leaves = Json::array();
  for (std::size_t o = 0; o < trees.size(); ++o) {
    for (const int leaf : trees[o].leaves()) {
      const core::HierarchyNode& node = trees[o].nodes()[static_cast<std::size_t>(leaf)];
      Json vertices = Json::array(), faces = Json::array();
      for (const Eigen::Vector3d& v : node.localMesh.vertices)
        vertices.push_back(Json::array({v.x(), v.y(), v.z()}));
      for (const core::Triangle& t : node.localMesh.triangles)
        faces.push_back(Json::array({t[0], t[1], t[2]}));
      leaves.push_back(
          {{"object", o}, {"path", node.path}, {"vertices", vertices}, {"faces", faces}});
    }
  }
  const int frames = scene.frames.value_or(100);
  Json poses = Json::array();
  for (int f = 0; f < frames; ++f) {
    Json frame = Json::array();
    for (core::ObjectTree& tree : trees) {
      tree.setFrame(f);
      for (const int leaf : tree.leaves()) {
        const Eigen::Matrix4d m = tree.nodes()[static_cast<std::size_t>(leaf)].world.matrix();
        Json rows = Json::array();
        for (int r = 0; r < 4; ++r)
          rows.push_back(Json::array({m(r, 0), m(r, 1), m(r, 2), m(r, 3)}));
        frame.push_back(rows);
      }
    }
    poses.push_back(frame);
  }
  return {{"name", std::string(info.name)}, {"leaves", leaves}, {"poses", poses}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: %s OUT.json [MAX_TRIANGLES_PER_BLOCK]\n", argv[0]);
    return 1;
  }
  try {
    const int triangles = argc > 2 ? std::stoi(argv[2]) : 128;
    Json scenes = Json::array();
    for (const core::BuiltinSceneInfo& info : core::builtinExperimentScenes())
      scenes.push_back(sceneJson(info, std::min(info.defaultTrianglesPerBlock, triangles)));
    std::ofstream out(argv[1]);
    out << Json{{"scenes", scenes}}.dump();
    return out ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
