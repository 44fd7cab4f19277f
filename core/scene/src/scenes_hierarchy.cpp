// Nine hierarchical objects (the paper's Figure 6 and Table 1: about 126,600 triangles, 36
// frames): a dumbbell, a table, a snowman, a rocket, a jack, a lamp, a chair, a molecule and
// a tree, each a union of convex blocks in a tree (the rocket's fins and the molecule's arms
// are groups of their own). They start on a 3 x 3 grid, turning slowly, and drift toward the
// middle, so that a few of them meet within the 36 frames.
#include <string>
#include <utility>
#include <vector>

#include "scene_builder.hpp"

namespace recode::core::detail {

namespace {

Json node(const std::string& name, const Block& block, const Json& position,
          const Json& rotation = Json()) {
  Json n;
  n["name"] = name;
  n["shape"] = block.shape;
  if (!position.is_null())
    n["position"] = position;
  if (!rotation.is_null())
    n["rotation_deg"] = rotation;
  return n;
}

Json group(const std::string& name, std::vector<Json> children, const Json& position = Json(),
           const Json& rotation = Json()) {
  Json n;
  n["name"] = name;
  if (!position.is_null())
    n["position"] = position;
  if (!rotation.is_null())
    n["rotation_deg"] = rotation;
  n["children"] = Json::array();
  for (Json& c : children)
    n["children"].push_back(std::move(c));
  return n;
}

// Cylinders and cones stand on their local z = 0; Ry(90) lays one along x.

Json dumbbell(int t) {
  return group("dumbbell", {node("bar", cylinderBlock(0.1, 1.6, t), vec(-0.8, 0, 0), vec(0, 90, 0)),
                            node("left weight", sphereBlock(0.35, t), vec(-0.8, 0, 0)),
                            node("right weight", sphereBlock(0.35, t), vec(0.8, 0, 0))});
}

// Four legs of a table or chair, at (+-offset, +-offset, z).
void addLegs(std::vector<Json>& parts, double radius, double length, double offset, double z,
             int t) {
  for (int i = 0; i < 4; ++i)
    parts.push_back(node("leg " + std::to_string(i), cylinderBlock(radius, length, t),
                         vec(i % 2 ? offset : -offset, i / 2 ? offset : -offset, z)));
}

Json table(int t) {
  std::vector<Json> parts = {node("top", cylinderBlock(0.7, 0.1, t), vec(0, 0, 0.35))};
  addLegs(parts, 0.06, 0.7, 0.4, -0.35, t);
  return group("table", parts);
}

Json snowman(int t) {
  return group("snowman",
               {node("base", sphereBlock(0.45, t), vec(0, 0, -0.5)),
                node("body", sphereBlock(0.35, t), vec(0, 0, 0.2)),
                node("head", sphereBlock(0.25, t), vec(0, 0, 0.75)),
                node("nose", coneBlock(0.06, 0.25, t), vec(0.2, 0, 0.75), vec(0, 90, 0))});
}

Json rocket(int t) {
  std::vector<Json> fins;
  for (int i = 0; i < 3; ++i)
    fins.push_back(
        node("fin " + std::to_string(i), ellipsoidBlock(0.3, 0.03, 0.2, t), vec(0.3, 0, 0)));
  // Each fin turned about z by its own group so the fins stand at 0, 120 and 240 degrees.
  std::vector<Json> finGroups;
  for (int i = 0; i < 3; ++i)
    finGroups.push_back(group("fin " + std::to_string(i), {fins[static_cast<std::size_t>(i)]},
                              Json(), vec(0, 0, 120.0 * i)));
  return group("rocket", {node("body", cappedConeBlock(0.25, 0.25, 1.0, t), vec(0, 0, -0.6)),
                          node("nose", coneBlock(0.25, 0.5, t), vec(0, 0, 0.4)),
                          group("fins", std::move(finGroups), vec(0, 0, -0.6))});
}

Json jack(int t) {
  return group("jack",
               {node("x", cappedConeBlock(0.1, 0.1, 1.2, t), vec(-0.6, 0, 0), vec(0, 90, 0)),
                node("y", cappedConeBlock(0.1, 0.1, 1.2, t), vec(0, -0.6, 0), vec(-90, 0, 0)),
                node("z", cappedConeBlock(0.1, 0.1, 1.2, t), vec(0, 0, -0.6)),
                node("hub", sphereBlock(0.2, t), vec(0, 0, 0))});
}

Json lamp(int t) {
  return group("lamp", {node("base", cylinderBlock(0.4, 0.08, t), vec(0, 0, -0.6)),
                        node("pole", cylinderBlock(0.04, 0.9, t), vec(0, 0, -0.52)),
                        node("shade", coneBlock(0.35, 0.4, t), vec(0, 0, 0.2)),
                        node("bulb", sphereBlock(0.12, t), vec(0, 0, 0.3))});
}

Json chair(int t) {
  std::vector<Json> parts = {node("seat", cylinderBlock(0.45, 0.08, t), vec(0, 0, 0)),
                             node("back", ellipsoidBlock(0.05, 0.4, 0.35, t), vec(-0.42, 0, 0.4))};
  addLegs(parts, 0.04, 0.55, 0.3, -0.55, t);
  return group("chair", parts);
}

Json molecule(int t) {
  // Four arms in tetrahedral directions (109.47 degrees apart).
  std::vector<Json> parts = {node("core", sphereBlock(0.3, t), vec(0, 0, 0))};
  const double tilts[4][3] = {{0, 0, 0}, {109.47, 0, 0}, {109.47, 0, 120}, {109.47, 0, 240}};
  for (int i = 0; i < 4; ++i) {
    const auto& r = tilts[i];
    parts.push_back(group("arm " + std::to_string(i),
                          {node("bond", cappedConeBlock(0.06, 0.06, 0.5, t), vec(0, 0, 0.25)),
                           node("atom", sphereBlock(0.18, t), vec(0, 0, 0.9))},
                          Json(), vec(r[0], r[1], r[2])));
  }
  return group("molecule", parts);
}

Json tree(int t) {
  return group("tree", {node("trunk", cylinderBlock(0.1, 0.5, t), vec(0, 0, -0.8)),
                        node("low", coneBlock(0.5, 0.6, t), vec(0, 0, -0.3)),
                        node("middle", coneBlock(0.4, 0.6, t), vec(0, 0, 0.0)),
                        node("top", coneBlock(0.3, 0.6, t), vec(0, 0, 0.3))});
}

std::vector<Json> makeObjects(int t) {
  return {dumbbell(t), table(t), snowman(t),  rocket(t), jack(t),
          lamp(t),     chair(t), molecule(t), tree(t)};
}

}  // namespace

Json makeHierarchyNineScene(int trianglesPerBlock) {
  constexpr double kSpacing = 2.2;
  std::vector<Json> objects = makeObjects(trianglesPerBlock);
  SceneRandom random(126600);
  Json list = Json::array();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const double x = (static_cast<int>(i % 3) - 1) * kSpacing;
    const double y = (static_cast<int>(i / 3) - 1) * kSpacing;
    Json o;  // placement first, so the file reads name, pose, motion, then the parts
    o["name"] = objects[i]["name"];
    o["position"] = vec(x, y, random.uniform(-0.3, 0.3));
    o["rotation_deg"] = Json::array(
        {random.uniform(-180, 180), random.uniform(-180, 180), random.uniform(-180, 180)});
    Json motion;
    motion["velocity"] =
        vec(-0.012 * x + random.uniform(-0.004, 0.004), -0.012 * y + random.uniform(-0.004, 0.004),
            random.uniform(-0.004, 0.004));
    motion["angular_velocity_deg"] =
        Json::array({random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)});
    o["motion"] = motion;
    o["children"] = std::move(objects[i]["children"]);
    list.push_back(o);
  }
  Json scene;
  Json view;
  view["axis"] = "z";
  scene["view"] = view;
  scene["frames"] = 36;
  scene["objects"] = list;
  return scene;
}

}  // namespace recode::core::detail
