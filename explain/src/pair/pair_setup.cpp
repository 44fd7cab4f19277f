#include "pair/pair_setup.hpp"

#include <charconv>
#include <stdexcept>

#include "recode/scene/builtin_scenes.hpp"

namespace recode::explain {

core::FrameSpec resolveFrameNamed(const core::Scene& scene, const core::Aabb& bounds,
                                  const core::FrameOverrides& overrides) {
  try {
    return core::resolveFrame(scene.view, bounds, overrides);
  } catch (const std::invalid_argument& e) {
    if (overrides.pixelSize)
      throw std::invalid_argument(std::string("--pixel-size: ") + e.what());
    if (overrides.width)
      throw std::invalid_argument(std::string("--resolution: ") + e.what());
    throw core::SceneError(scene.sourceName, "view", e.what());
  }
}

PairSetup pairSetupFromScene(const core::Scene& scene, const core::FrameOverrides& overrides) {
  if (scene.objects.size() < 2)
    throw core::SceneError(
        scene.sourceName, "objects",
        "a pair needs at least two objects, the file has " + std::to_string(scene.objects.size()));
  PairSetup s;
  s.source = scene.sourceName;
  s.nameA = scene.objects[0].name;
  s.nameB = scene.objects[1].name;
  for (int i = 0; i < 2; ++i) {
    const core::SceneObject& o = scene.objects[static_cast<std::size_t>(i)];
    if (!o.isLeaf())
      throw core::SceneError(scene.sourceName, o.jsonPath,
                             "a pair needs two blocks (convex or closed meshes), and this object "
                             "has children (recode run handles objects made of several blocks)");
  }
  s.a = scene.objects[0].worldMesh();
  s.b = scene.objects[1].worldMesh();
  s.closedA = scene.objects[0].closed;
  s.closedB = scene.objects[1].closed;
  core::Aabb bounds = core::boundingBox(s.a);
  bounds.extend(core::boundingBox(s.b));
  s.frame = resolveFrameNamed(scene, bounds, overrides);
  return s;
}

PairSetup loadPairSetup(const std::optional<std::string>& scenePath,
                        const core::FrameOverrides& overrides) {
  if (scenePath)
    return pairSetupFromScene(core::loadScene(*scenePath), overrides);
  return pairSetupFromScene(core::builtinPairScene(), overrides);
}

core::FrameOverrides parseResolution(const std::string& text) {
  const auto fail = [&]() -> core::FrameOverrides {
    throw std::invalid_argument("--resolution '" + text +
                                "': expected W or WxH with whole numbers in 1..16384");
  };
  const auto number = [&](std::string_view part) {
    int value = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (ec != std::errc() || end != part.data() + part.size() || part.empty() || value < 1 ||
        value > raster::kMaxFramebufferSize)
      fail();
    return value;
  };
  core::FrameOverrides o;
  const std::string_view all(text);
  const std::size_t x = all.find('x');
  if (x == std::string_view::npos) {
    o.width = number(all);
  } else {
    o.width = number(all.substr(0, x));
    o.height = number(all.substr(x + 1));
  }
  return o;
}

}  // namespace recode::explain
