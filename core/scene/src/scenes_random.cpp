// Objects in random motion in a box (the paper's "100 cones randomly placed in space" and
// Figure 7's flat ellipsoids, truncated cones with spherical caps and cones): random
// position, orientation, velocity and spin from a fixed seed, each object bouncing between
// the walls of the box. Objects may pass into each other (there is no collision response), as
// in the paper.
#include <string>

#include "scene_builder.hpp"

namespace recode::core::detail {

namespace {

constexpr int kObjects = 100;
constexpr double kHalfBox = 6.0;
constexpr double kMaxSpeed = 0.08;  // per axis, world units per frame
constexpr double kMaxSpin = 4.0;    // per axis, degrees per frame

}  // namespace

Json makeRandomScene(bool conesOnly, int trianglesPerBlock) {
  Json scene;
  Json view;
  view["axis"] = "z";
  scene["view"] = view;
  scene["frames"] = 100;
  const auto part = [](const Block& block) {
    Json p;
    p["shape"] = block.shape;
    return p;
  };
  Json parts;
  parts["cone"] = part(coneBlock(0.4, 1.2, trianglesPerBlock));
  if (!conesOnly) {
    parts["flat ellipsoid"] = part(ellipsoidBlock(0.6, 0.4, 0.12, trianglesPerBlock));
    parts["capped cone"] = part(cappedConeBlock(0.3, 0.15, 0.8, trianglesPerBlock));
  }
  scene["parts"] = parts;
  static const char* const kKinds[] = {"flat ellipsoid", "capped cone", "cone"};
  SceneRandom random(conesOnly ? 1999 : 7);
  Json objects = Json::array();
  const Json box =
      Json::array({vec(-kHalfBox, -kHalfBox, -kHalfBox), vec(kHalfBox, kHalfBox, kHalfBox)});
  for (int i = 0; i < kObjects; ++i) {
    const std::string kind = conesOnly ? "cone" : kKinds[i % 3];
    Json o;
    o["name"] = kind + " " + std::to_string(i);
    o["part"] = kind;
    const auto inBox = [&] { return random.uniform(-kHalfBox, kHalfBox); };
    o["position"] = Json::array({inBox(), inBox(), inBox()});
    const auto angle = [&] { return random.uniform(-180.0, 180.0); };
    o["rotation_deg"] = Json::array({angle(), angle(), angle()});
    Json motion;
    const auto speed = [&] { return random.uniform(-kMaxSpeed, kMaxSpeed); };
    motion["velocity"] = Json::array({speed(), speed(), speed()});
    const auto spin = [&] { return random.uniform(-kMaxSpin, kMaxSpin); };
    motion["angular_velocity_deg"] = Json::array({spin(), spin(), spin()});
    motion["bounce_within"] = box;
    o["motion"] = motion;
    objects.push_back(o);
  }
  scene["objects"] = objects;
  return scene;
}

}  // namespace recode::core::detail
