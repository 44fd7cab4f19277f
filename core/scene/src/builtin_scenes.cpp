#include "recode/scene/builtin_scenes.hpp"

#include "recode/geometry/generators.hpp"

namespace recode::core {

Scene builtinPairScene() {
  Scene scene;
  scene.sourceName = "built-in pair";
  scene.view.axis = ViewAxis::X;
  scene.view.resolution = std::array<int, 2>{256, 256};
  SceneObject a;
  a.name = "lower cone";
  a.jsonPath = "objects[0]";
  a.localMesh = makeCone(1.0, 2.0, 32);
  SceneObject b = a;
  b.name = "upper cone";
  b.jsonPath = "objects[1]";
  b.position = {0.0, 0.0, 3.75};
  b.rotationDeg = {180.0, 0.0, 0.0};
  scene.objects = {a, b};
  return scene;
}

}  // namespace recode::core
