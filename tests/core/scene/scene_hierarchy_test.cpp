// Scene files with hierarchies and motion: children, parts (shared geometry), motion with
// bouncing, keyframes and joints parse with their values; every broken form (cycle among
// parts, duplicate child names, bad joints, bad keyframes, ...) gives a message naming the
// JSON path and the problem.

#include <catch2/catch.hpp>

#include <string>

#include "recode/geometry/generators.hpp"
#include "recode/scene/scene.hpp"
#include "scene_test_support.hpp"

using namespace recode::core;
using Catch::Matchers::StartsWith;
using recode::core::test::dataFile;

namespace {

Scene parse(const std::string& text) {
  return test::parseSceneText(text, "h.json");
}

std::string errorOf(const std::string& text) {
  return test::sceneErrorOf(text, "h.json");
}

const std::string kBox = R"("shape": {"type": "box", "size": [1, 1, 1]})";

// One object with the given members (without braces).
std::string oneObject(const std::string& body) {
  return R"({"objects": [{)" + body + "}]}";
}

}  // namespace

TEST_CASE("scene hierarchy: children, parts and motion parse with their values", "[scene]") {
  const Scene scene = parse(R"({
    "frames": 40,
    "parts": {
      "tooth": {"shape": {"type": "cone", "radius": 0.5, "height": 2, "segments": 8}},
      "pair": {"children": [{"name": "left", "part": "tooth", "position": [-1, 0, 0]},
                            {"name": "right", "part": "tooth", "position": [1, 0, 0]}]}
    },
    "objects": [
      {"name": "comb", "position": [0, 0, 1],
       "motion": {"velocity": [0, 0, -0.1], "angular_velocity_deg": [0, 0, 2],
                  "bounce_within": [[-5, -5, -5], [5, 5, 5]]},
       "children": [
         {"name": "front", "part": "pair"},
         {"name": "back", "part": "pair", "position": [0, 3, 0],
          "joint": {"axis": [0, 2, 0], "angle_deg": 5, "rate_deg": 1.5, "min_deg": 0,
                    "max_deg": 45}},
         {"shape": {"type": "sphere", "radius": 0.25, "segments": 6, "rings": 3},
          "keyframes": [{"frame": 0}, {"frame": 10, "position": [1, 2, 3]},
                        {"frame": 20, "rotation_deg": [0, 90, 0]}]}
       ]},
      {"part": "tooth"}
    ]})");
  CHECK(scene.frames == 40);
  REQUIRE(scene.objects.size() == 2);
  const SceneObject& comb = scene.objects[0];
  CHECK(comb.name == "comb");
  CHECK_FALSE(comb.isLeaf());
  CHECK(comb.localMesh.triangleCount() == 0);
  REQUIRE(comb.motion.has_value());
  REQUIRE(comb.motion->bounceWithin.has_value());
  CHECK(comb.motion->bounceWithin->min == Eigen::Vector3d(-5, -5, -5));
  CHECK(comb.motion->angularVelocityDeg == Eigen::Vector3d(0, 0, 2));
  REQUIRE(comb.children.size() == 3);

  const SceneObject& front = comb.children[0];
  CHECK(front.name == "front");
  CHECK(front.jsonPath == "objects[0].children[0]");
  REQUIRE(front.children.size() == 2);
  CHECK(front.children[0].name == "left");
  CHECK(front.children[0].position == Eigen::Vector3d(-1, 0, 0));
  CHECK(front.children[1].position == Eigen::Vector3d(1, 0, 0));
  const TriangleMesh tooth = makeCone(0.5, 2, 8);
  CHECK(front.children[0].localMesh.vertices == tooth.vertices);
  CHECK(front.children[1].localMesh.triangles == tooth.triangles);

  const SceneObject& back = comb.children[1];
  CHECK(back.position == Eigen::Vector3d(0, 3, 0));
  REQUIRE(back.joint.has_value());
  CHECK(back.joint->axis == Eigen::Vector3d(0, 1, 0));  // normalised
  CHECK(back.joint->angleDeg == 5.0);
  CHECK(back.joint->rateDeg == 1.5);
  CHECK(back.joint->minDeg == 0.0);
  CHECK(back.joint->maxDeg == 45.0);
  REQUIRE(back.children.size() == 2);  // the part's own children, placed as in the part

  const SceneObject& ball = comb.children[2];
  CHECK(ball.name == "child 2");
  REQUIRE(ball.keyframes.size() == 3);
  CHECK(ball.keyframes[0].position == Eigen::Vector3d::Zero());  // defaults: the node's own
  CHECK(ball.keyframes[1].frame == 10);
  CHECK(ball.keyframes[1].position == Eigen::Vector3d(1, 2, 3));
  CHECK(ball.keyframes[2].rotationDeg == Eigen::Vector3d(0, 90, 0));
  CHECK(ball.keyframes[2].position == Eigen::Vector3d::Zero());

  const SceneObject& single = scene.objects[1];
  CHECK(single.name == "object 1");
  CHECK(single.isLeaf());
  CHECK(single.localMesh.vertices == tooth.vertices);
}

TEST_CASE("scene hierarchy errors: parts", "[scene][errors]") {
  CHECK_THAT(errorOf(oneObject(R"("part": "gear")")),
             StartsWith("h.json: objects[0].part: no part named \"gear\" (parts: none defined)"));
  CHECK_THAT(errorOf(R"({"parts": {"a": {)" + kBox + R"(}, "b": {)" + kBox +
                     R"(}}, "objects": [{"part": "c"}]})"),
             StartsWith("h.json: objects[0].part: no part named \"c\" (parts: a, b)"));
  // A cycle through two parts, reported where the loop closes.
  CHECK_THAT(errorOf(R"({"parts": {"a": {"children": [{"part": "b"}]},
                                    "b": {"children": [{"name": "x", "part": "a"}]}},
                         "objects": [{"part": "a"}]})"),
             StartsWith("h.json: parts.b.children[0].part: part \"a\" contains itself "
                        "(a -> b -> a); parts must not form a cycle"));
  CHECK_THAT(errorOf(R"({"parts": {"a": {"children": [{"part": "a"}]}},
                         "objects": [{)" +
                     kBox + R"(}]})"),
             StartsWith("h.json: parts.a.children[0].part: part \"a\" contains itself (a -> a)"));
  CHECK_THAT(errorOf(R"({"parts": {"a": {)" + kBox + R"(, "position": [1, 0, 0]}},
                         "objects": [{"part": "a"}]})"),
             StartsWith("h.json: parts.a.position: unknown key for a part (a part is geometry "
                        "only; place it where it is used) (allowed: mesh, hull, parts_from_groups, "
                        "closed, shape, children)"));
  CHECK_THAT(errorOf(R"({"parts": [], "objects": [{)" + kBox + "}]}"),
             StartsWith("h.json: parts: expected an object of named parts, got an array"));
  // An unused part is still checked.
  CHECK_THAT(errorOf(R"({"parts": {"a": {"shape": {"type": "cone", "radius": -1, "height": 1}}},
                         "objects": [{)" +
                     kBox + R"(}]})"),
             StartsWith("h.json: parts.a.shape.radius: expected a positive number, got -1"));
  // Parts inside parts multiply: 10^6 blocks are refused before they are all built.
  std::string parts = R"("p0": {)" + kBox + "}";
  for (int i = 1; i <= 6; ++i) {
    std::string children;
    for (int c = 0; c < 10; ++c)
      children += std::string(c ? ", " : "") + R"({"name": "c)" + std::to_string(c) +
                  R"(", "part": "p)" + std::to_string(i - 1) + R"("})";
    parts += R"(, "p)" + std::to_string(i) + R"(": {"children": [)" + children + "]}";
  }
  CHECK_THAT(errorOf(R"({"parts": {)" + parts + R"(}, "objects": [{"part": "p6"}]})"),
             Catch::Matchers::Contains("more than 100000 blocks in the scene"));
}

// The scene's triangle budget counts every use of a part again, and refuses a generated shape
// from its parameters, before it is built.
TEST_CASE("scene triangle budget", "[scene][errors][limits]") {
  const std::string cone = R"("shape": {"type": "cone", "radius": 1, "height": 1, "segments": 50})";
  const std::string tenCones = R"({"parts": {"c": {)" + cone + R"(},
      "ten": {"children": [{"name": "0", "part": "c"}, {"name": "1", "part": "c"}, {"name": "2",
        "part": "c"}, {"name": "3", "part": "c"}, {"name": "4", "part": "c"}, {"name": "5",
        "part": "c"}, {"name": "6", "part": "c"}, {"name": "7", "part": "c"}, {"name": "8",
        "part": "c"}, {"name": "9", "part": "c"}]}},
    "objects": [{"part": "ten"}, {"part": "ten"}]})";
  const auto errorWithLimit = [](const std::string& text, std::size_t maxTriangles) {
    try {
      (void)parseScene(text, "t.json", ".", SceneReadLimits{maxTriangles});
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  // 20 cones of 100 triangles: 2000 fit exactly, 1999 do not; the second "ten" is refused
  // where it is used.
  CHECK(errorWithLimit(tenCones, 2000) == "(no error)");
  CHECK(parseScene(tenCones, "t.json", ".", SceneReadLimits{2000}).objects.size() == 2);
  CHECK(errorWithLimit(tenCones, 1999) ==
        "t.json: objects[1].part: this block would bring the scene to 2000 triangles, over the "
        "limit of 1999 triangles in a scene (each use of a part counts again)");
  // Within the first use of "ten", the tenth cone is one too many.
  CHECK_THAT(errorWithLimit(tenCones, 999),
             StartsWith("t.json: parts.ten.children[9].part: this block would bring the scene to "
                        "1000 triangles"));
  // The default limit, 2^25, refuses a sphere of 2 * 99,999 * 100,000 triangles unbuilt.
  CHECK(kMaxSceneTriangles == (std::size_t{1} << 25));
  CHECK(errorOf(oneObject(R"("shape": {"type": "sphere", "radius": 1, "segments": 100000,
                                       "rings": 100000})")) ==
        "h.json: objects[0].shape: this block would bring the scene to 19999800000 triangles, over "
        "the limit of 33554432 triangles in a scene (each use of a part counts again)");
}

TEST_CASE("scene hierarchy errors: children", "[scene][errors]") {
  CHECK_THAT(errorOf(oneObject(R"("name": "hand", "children": [{"name": "thumb", )" + kBox +
                               R"(}, {"name": "index", )" + kBox + R"(}, {"name": "thumb", )" +
                               kBox + "}]")),
             StartsWith("h.json: objects[0].children[2]: duplicate name \"thumb\" (also "
                        "objects[0].children[0]); children of one object need distinct names"));
  CHECK_THAT(errorOf(oneObject(R"("children": {"a": 1})")),
             StartsWith("h.json: objects[0].children: expected an array of objects, got an "
                        "object"));
  CHECK_THAT(errorOf(oneObject(R"("children": [{"position": [0, 0, 0]}])")),
             StartsWith("h.json: objects[0].children[0]: missing \"mesh\", \"shape\", "
                        "\"children\" or \"part\""));
  CHECK_THAT(errorOf(oneObject(R"("children": [{)" + kBox + R"(}], )" + kBox)),
             StartsWith("h.json: objects[0]: give exactly one of \"mesh\", \"shape\", "
                        "\"children\" and \"part\", got \"shape\" and \"children\""));
  CHECK_THAT(errorOf(oneObject(R"("children": [{"shape": {"type": "box", "size": [1, 0, 1]}}])")),
             StartsWith("h.json: objects[0].children[0].shape.size[1]: expected a positive "
                        "number, got 0"));
  std::string deep = "{" + kBox + "}";
  for (int i = 0; i < 40; ++i)
    deep = R"({"children": [)" + deep + "]}";
  CHECK_THAT(errorOf(R"({"objects": [)" + deep + "]}"),
             Catch::Matchers::Contains(": objects nested more than 32 levels deep"));
}

TEST_CASE("scene hierarchy errors: joints", "[scene][errors]") {
  const auto withJoint = [](const std::string& joint) {
    return errorOf(oneObject(kBox + R"(, "joint": )" + joint));
  };
  CHECK_THAT(withJoint(R"({"rate_deg": 1})"),
             StartsWith("h.json: objects[0].joint: missing key \"axis\" (the hinge direction"));
  CHECK_THAT(withJoint(R"({"axis": [0, 0, 0]})"),
             StartsWith("h.json: objects[0].joint.axis: expected a non-zero direction, got "
                        "[0,0,0]"));
  CHECK_THAT(withJoint(R"({"axis": [0, 1, 0], "min_deg": 30, "max_deg": 10})"),
             StartsWith("h.json: objects[0].joint: min_deg (30) must not exceed max_deg (10)"));
  CHECK_THAT(withJoint(R"({"axis": [0, 1, 0], "angle_deg": -5, "min_deg": 0})"),
             StartsWith("h.json: objects[0].joint.angle_deg: the starting angle -5.0 lies "
                        "outside [0.0, inf] (min_deg, max_deg)"));
  CHECK_THAT(withJoint(R"({"axis": [0, 1, 0], "speed": 3})"),
             StartsWith("h.json: objects[0].joint.speed: unknown key (allowed: axis, angle_deg, "
                        "rate_deg, min_deg, max_deg)"));
  CHECK_THAT(withJoint(R"({"axis": [0, 1, 0], "rate_deg": "fast"})"),
             StartsWith("h.json: objects[0].joint.rate_deg: expected a number, got a string"));
  CHECK_THAT(withJoint("[0, 1, 0]"),
             StartsWith("h.json: objects[0].joint: expected an object, got an array"));
}

TEST_CASE("scene hierarchy errors: keyframes and motion", "[scene][errors]") {
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "keyframes": [{"frame": 5}, {"frame": 5}])")),
             StartsWith("h.json: objects[0].keyframes[1].frame: keyframes must be in increasing "
                        "frame order; got 5 after 5"));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "keyframes": [{"position": [0, 0, 0]}])")),
             StartsWith("h.json: objects[0].keyframes[0]: missing key \"frame\""));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "keyframes": [{"frame": -1}])")),
             StartsWith("h.json: objects[0].keyframes[0].frame: expected an integer in "
                        "0..2147483647, got -1"));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "keyframes": [])")),
             StartsWith("h.json: objects[0].keyframes: expected at least one keyframe"));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "keyframes": [{"frame": 0}], "motion": {})")),
             StartsWith("h.json: objects[0]: give at most one of \"motion\" and \"keyframes\""));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "motion": {"bounce_within": [[0, 0, 0], [1, -1, 1]]})")),
             StartsWith("h.json: objects[0].motion.bounce_within: the first corner must not "
                        "exceed the second (0 > -1 along y)"));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "position": [0, 0, 2],
                               "motion": {"bounce_within": [[-1, -1, -1], [1, 1, 1]]})")),
             StartsWith("h.json: objects[0].motion.bounce_within: the object's position 2.0 "
                        "along z lies outside the box"));
  CHECK_THAT(errorOf(oneObject(kBox + R"(, "motion": {"bounce_within": [0, 0]})")),
             StartsWith("h.json: objects[0].motion.bounce_within[0]: expected an array of 3"));
}
