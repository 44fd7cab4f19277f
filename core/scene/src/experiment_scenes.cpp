// The registry of built-in experiment scenes: names, defaults, JSON text and scenes.
#include "recode/scene/experiment_scenes.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "scene_builder.hpp"

namespace recode::core {

namespace {

constexpr std::array<BuiltinSceneInfo, 8> kScenes = {{
    {"comb-translate-aligned",
     "two combs of five cones, tips aligned; one translates until all five tip pairs meet", 64},
    {"comb-translate-offset",
     "two combs, tips offset half a spacing; boxes overlap long before the sides meet", 64},
    {"comb-rotate-aligned", "two combs, tips aligned and just overlapping; one turns about z", 64},
    {"comb-rotate-offset", "two combs, tips offset; one turns about z, boxes cross, no contact",
     64},
    {"random-cones", "100 cones in random motion bouncing in a box, 100 frames", 64},
    {"random-shapes",
     "100 flat ellipsoids, capped cones and cones in random motion, 100 frames (the paper's "
     "3,600 to 1,152,000 triangles: 36 to 11,520 per block)",
     36},
    {"hand-grasp",
     "two hands (palm + 3 phalanges per finger) closing on a ball until every finger touches "
     "it (the paper's Table 2: 1,860 to 76,032 triangles, about 56 to 2,304 per block)",
     128},
    {"hierarchy-9", "nine hierarchical objects drifting together, 36 frames (the paper's Table 1)",
     2880},
}};

}  // namespace

std::span<const BuiltinSceneInfo> builtinExperimentScenes() {
  return kScenes;
}

const BuiltinSceneInfo* findBuiltinExperimentScene(std::string_view name) {
  const auto it = std::find_if(kScenes.begin(), kScenes.end(),
                               [&](const BuiltinSceneInfo& s) { return s.name == name; });
  return it == kScenes.end() ? nullptr : &*it;
}

std::string builtinSceneJson(std::string_view name, std::optional<int> trianglesPerBlock) {
  const BuiltinSceneInfo* info = findBuiltinExperimentScene(name);
  if (!info) {
    std::string names;
    for (const BuiltinSceneInfo& s : kScenes)
      names += (names.empty() ? "" : ", ") + std::string(s.name);
    throw std::invalid_argument("unknown built-in scene \"" + std::string(name) +
                                "\" (built-ins: " + names + ")");
  }
  const int t = trianglesPerBlock.value_or(info->defaultTrianglesPerBlock);
  if (t < kMinTrianglesPerBlock || t > kMaxTrianglesPerBlock) {
    throw std::invalid_argument("triangles per block " + std::to_string(t) + " is outside " +
                                std::to_string(kMinTrianglesPerBlock) + ".." +
                                std::to_string(kMaxTrianglesPerBlock));
  }
  using namespace detail;
  Json scene;
  if (name == "comb-translate-aligned")
    scene = makeCombScene(false, false, t);
  else if (name == "comb-translate-offset")
    scene = makeCombScene(false, true, t);
  else if (name == "comb-rotate-aligned")
    scene = makeCombScene(true, false, t);
  else if (name == "comb-rotate-offset")
    scene = makeCombScene(true, true, t);
  else if (name == "random-cones")
    scene = makeRandomScene(true, t);
  else if (name == "random-shapes")
    scene = makeRandomScene(false, t);
  else if (name == "hand-grasp")
    scene = makeHandGraspScene(t);
  else
    scene = makeHierarchyNineScene(t);
  return sceneText(scene);
}

Scene builtinExperimentScene(std::string_view name, std::optional<int> trianglesPerBlock) {
  const std::string text = builtinSceneJson(name, trianglesPerBlock);
  return parseScene(text, "built-in " + std::string(name), ".");
}

}  // namespace recode::core
