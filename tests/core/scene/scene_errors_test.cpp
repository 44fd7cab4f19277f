// Scene files that are not valid: one test per kind of error, each checking the JSON path and
// the problem in the message.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <string>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/scene/scene.hpp"
#include "scene_test_support.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using recode::core::test::dataFile;
using recode::core::test::errorOf;
using recode::core::test::oneObject;
using recode::core::test::oneShape;
using recode::core::test::parse;
using recode::core::test::TempDir;

// ---- errors ------------------------------------------------------------------------------

TEST_CASE("scene errors: malformed JSON gives line and column", "[scene][errors]") {
  // Missing comma: the unexpected '"' is line 3, column 3.
  const std::string text = "{\n  \"frames\": 2\n  \"objects\": []\n}\n";
  try {
    (void)parse(text);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK_THAT(e.what(), StartsWith("s.json:3:3: invalid JSON: "));
    CHECK_THAT(e.what(), Contains("syntax error"));
    CHECK(e.line() == 3);
    CHECK(e.column() == 3);
    CHECK(e.jsonPath().empty());
  }
  CHECK_THAT(errorOf(""), StartsWith("s.json:1:1: invalid JSON: "));
  // Errors point at the start of the offending token.
  CHECK_THAT(errorOf("{\"objects\":\n   tru}"), StartsWith("s.json:2:7: invalid JSON: "));
  CHECK_THAT(errorOf("{\"objects\": [1, 2"), StartsWith("s.json:1:18: invalid JSON: "));
  CHECK_THAT(errorOf("{\"a\": 1 \"b\": 2}"), StartsWith("s.json:1:9: invalid JSON: "));
  CHECK_THAT(errorOf("{\"objects\": [1, 2,]}"), StartsWith("s.json:1:19: invalid JSON: "));
  CHECK_THAT(errorOf("{\"objects\": []} x"), StartsWith("s.json:1:17: invalid JSON: "));
  // A number beyond the double range is rejected, not read as infinity.
  const std::string huge =
      errorOf("{\n\"frames\": 1,\n\"objects\": [{\"position\": [0, 1e400, 0]}]}");
  CHECK_THAT(huge, StartsWith("s.json:3:"));
  CHECK_THAT(huge, Contains("1e400"));
}

TEST_CASE("scene errors: nesting deeper than the JSON layer reads", "[scene][errors]") {
  // 100,000 nested arrays (a 200 KB file) are refused at once, before they cost memory.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  CHECK(errorOf(deep) == "s.json: arrays and objects nested more than 128 deep");
  const std::string deepObjects = R"({"objects": [{"children": )" + deep + "}]}";
  CHECK(errorOf(deepObjects) == "s.json: arrays and objects nested more than 128 deep");
  // 128 levels are still read (and then refused by the scene's own rules, not the layer's).
  const std::string limit = std::string(127, '[') + std::string(127, ']');
  CHECK_THAT(errorOf(R"({"objects": )" + limit + "}"), !Contains("nested more than 128"));
}

TEST_CASE("scene errors: duplicate keys", "[scene][errors]") {
  CHECK_THAT(errorOf(R"({"frames": 1, "frames": 2, "objects": []})"),
             StartsWith("s.json: frames: duplicate key"));
  CHECK_THAT(errorOf(oneShape(R"("type": "sphere", "radius": 1, "radius": 2)")),
             StartsWith("s.json: objects[0].shape.radius: duplicate key"));
}

TEST_CASE("scene errors: unknown keys", "[scene][errors]") {
  const std::string box = R"("shape": {"type": "box", "size": [1, 1, 1]})";
  CHECK_THAT(errorOf(R"({"objects": [{)" + box + R"(}], "camera": {}})"),
             StartsWith("s.json: camera: unknown key (allowed: view, objects, frames, parts)"));
  CHECK_THAT(errorOf(R"({"view": {"axis": "z", "zoom": 2}, "objects": [{)" + box + "}]}"),
             StartsWith("s.json: view.zoom: unknown key"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "color": "red")")),
             StartsWith("s.json: objects[0].color: unknown key"));
  CHECK_THAT(errorOf(oneShape(R"("type": "cone", "radius": 1, "height": 1, "rings": 4)")),
             StartsWith("s.json: objects[0].shape.rings: unknown key for a cone shape "
                        "(allowed: type, radius, height, segments)"));
  CHECK_THAT(errorOf(oneShape(R"("type": "box", "size": [1, 1, 1], "radius": 1)")),
             StartsWith("s.json: objects[0].shape.radius: unknown key for a box shape"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "motion": {"velocity": [0, 0, 1], "spin": 3})")),
             StartsWith("s.json: objects[0].motion.spin: unknown key"));
  // A key that is not an identifier is quoted in the path.
  CHECK_THAT(errorOf(oneObject(box + R"(, "my key": 1)")),
             StartsWith("s.json: objects[0][\"my key\"]: unknown key"));
}

TEST_CASE("scene errors: wrong types name what was expected and found", "[scene][errors]") {
  const std::string box = R"("shape": {"type": "box", "size": [1, 1, 1]})";
  CHECK_THAT(errorOf("[]"), StartsWith("s.json: (root): expected an object, got an array"));
  CHECK_THAT(errorOf(oneShape(R"("type": "sphere", "radius": "2")")),
             StartsWith("s.json: objects[0].shape.radius: expected a positive number, got a "
                        "string"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "position": [0, "1", 0])")),
             StartsWith("s.json: objects[0].position[1]: expected a number, got a string"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "position": [0, null, 0])")),
             StartsWith("s.json: objects[0].position[1]: expected a number, got null"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "position": [0, 1])")),
             StartsWith("s.json: objects[0].position: expected an array of 3 numbers [x, y, z], "
                        "got 2 elements"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "rotation_deg": {"x": 1})")),
             StartsWith("s.json: objects[0].rotation_deg: expected an array of 3 numbers"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "name": 7)")),
             StartsWith("s.json: objects[0].name: expected a string, got 7"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "motion": [1, 2, 3])")),
             StartsWith("s.json: objects[0].motion: expected an object, got an array"));
  CHECK_THAT(errorOf(oneObject(box + R"(, "motion": {"angular_velocity_deg": [0, true, 0]})")),
             StartsWith("s.json: objects[0].motion.angular_velocity_deg[1]: expected a number, "
                        "got true"));
  CHECK_THAT(errorOf(R"({"objects": {"a": 1}})"),
             StartsWith("s.json: objects: expected an array of objects, got an object"));
  CHECK_THAT(errorOf(R"({"objects": ["cube.obj"]})"),
             StartsWith("s.json: objects[0]: expected an object, got a string"));
  CHECK_THAT(errorOf(R"({"view": 3, "objects": [{)" + box + "}]}"),
             StartsWith("s.json: view: expected an object, got 3"));
  CHECK_THAT(errorOf(oneObject(R"("shape": "cone")")),
             StartsWith("s.json: objects[0].shape: expected an object, got a string"));
  CHECK_THAT(errorOf(oneObject(R"("mesh": ["a.obj"])")),
             StartsWith("s.json: objects[0].mesh: expected a string, got an array"));
  CHECK_THAT(errorOf(oneShape(R"("type": "sphere", "radius": 1, "segments": 12.5)")),
             StartsWith("s.json: objects[0].shape.segments: expected an integer in "
                        "3..2147483647, got 12.5"));
}

TEST_CASE("scene errors: view axis and window", "[scene][errors]") {
  const auto withView = [](const std::string& view) {
    return errorOf(R"({"view": )" + view +
                   R"(, "objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}]})");
  };
  CHECK_THAT(withView(R"({"axis": "w"})"),
             StartsWith(R"(s.json: view.axis: expected "x", "y" or "z", got "w")"));
  CHECK_THAT(withView(R"({"axis": "Z"})"), StartsWith("s.json: view.axis: expected"));
  CHECK_THAT(withView(R"({"axis": 2})"),
             StartsWith(R"(s.json: view.axis: expected "x", "y" or "z", got 2)"));
  CHECK_THAT(withView(R"({"window": [0, 0, 1]})"),
             StartsWith("s.json: view.window: expected an array of 4 numbers [umin, vmin, umax, "
                        "vmax], got 3 elements"));
  CHECK_THAT(withView(R"({"window": [0, 0, "1", 1]})"),
             StartsWith("s.json: view.window[2]: expected a number, got a string"));
  CHECK_THAT(withView(R"({"window": [2, 0, 1, 1]})"),
             StartsWith("s.json: view.window: umin (2) must be less than umax (1)"));
  CHECK_THAT(withView(R"({"window": [0, 1, 1, 1]})"),
             StartsWith("s.json: view.window: vmin (1) must be less than vmax (1)"));
  // Coordinates within +-1e9 and sides of at least 1e-6: the value, the rule, numbers short.
  CHECK(withView(R"({"window": [-1e308, 0, 1e308, 1]})") ==
        "s.json: view.window[0]: expected a number in -1e+09..1e+09 (world units), got -1e+308");
  CHECK(withView(R"({"window": [1e17, 0, 1.1e17, 1]})") ==
        "s.json: view.window[0]: expected a number in -1e+09..1e+09 (world units), got 1e+17");
  CHECK(withView(R"({"window": [0, 0, 1e-300, 1e-300]})") ==
        "s.json: view.window: the window's height 1e-300 is below the smallest side, 1e-06 world "
        "units");
  CHECK(withView(R"({"window": [0, 0, 1e-7, 1]})") ==
        "s.json: view.window: the window's width 1e-07 is below the smallest side, 1e-06 world "
        "units");
}

// Every number of a scene is bounded so that poses stay finite over 1,000,000 frames
// (scene.hpp, docs/scenes.md "Ranges"): 1e160 degrees per frame once squared to infinity and
// posed the object at NaN, which `recode run` reported as no contact.
TEST_CASE("scene errors: numbers out of their ranges", "[scene][errors]") {
  const std::string box = R"("shape": {"type": "box", "size": [1, 1, 1]})";
  const auto withPlacement = [&](const std::string& placement) {
    return errorOf(oneObject(box + ", " + placement));
  };
  const std::string rate = "(degrees per frame, so that 1,000,000 frames stay finite)";
  CHECK(withPlacement(R"("motion": {"angular_velocity_deg": [1e160, 0, 0]})") ==
        "s.json: objects[0].motion.angular_velocity_deg[0]: expected a number in -1e+06..1e+06 " +
            rate + ", got 1e+160");
  CHECK(withPlacement(R"("motion": {"angular_velocity_deg": [0, 0, -1e308]})") ==
        "s.json: objects[0].motion.angular_velocity_deg[2]: expected a number in -1e+06..1e+06 " +
            rate + ", got -1e+308");
  CHECK(withPlacement(R"("motion": {"velocity": [0, 1e200, 0]})") ==
        "s.json: objects[0].motion.velocity[1]: expected a number in -1000..1000 (world units "
        "per frame, so that 1,000,000 frames stay finite), got 1e+200");
  CHECK(withPlacement(R"("joint": {"axis": [0, 0, 1], "rate_deg": 1e300})") ==
        "s.json: objects[0].joint.rate_deg: expected a number in -1e+06..1e+06 " + rate +
            ", got 1e+300");
  CHECK(withPlacement(R"("joint": {"axis": [0, 0, 1], "angle_deg": 1e7})") ==
        "s.json: objects[0].joint.angle_deg: expected a number in -1e+06..1e+06 (degrees), got "
        "10000000.0");
  CHECK(withPlacement(R"("joint": {"axis": [1e300, 0, 1]})") ==
        "s.json: objects[0].joint.axis[0]: expected a number in -1e+09..1e+09 (a direction), got "
        "1e+300");
  CHECK(withPlacement(R"("position": [1e17, 0, 0])") ==
        "s.json: objects[0].position[0]: expected a number in -1e+09..1e+09 (world units), got "
        "1e+17");
  CHECK(withPlacement(R"("rotation_deg": [0, 1e100, 0])") ==
        "s.json: objects[0].rotation_deg[1]: expected a number in -1e+06..1e+06 (degrees), got "
        "1e+100");
  CHECK(withPlacement(R"("position": [0, 0, 0], "motion": {"velocity": [1, 0, 0], )"
                      R"("bounce_within": [[-1e300, -1, -1], [1, 1, 1]]})") ==
        "s.json: objects[0].motion.bounce_within[0][0]: expected a number in -1e+09..1e+09 "
        "(world units), got -1e+300");
  CHECK(withPlacement(R"("keyframes": [{"frame": 0, "position": [0, 0, 1e10]}])") ==
        "s.json: objects[0].keyframes[0].position[2]: expected a number in -1e+09..1e+09 (world "
        "units), got 10000000000.0");
  CHECK(errorOf(oneShape(R"("type": "box", "size": [1e308, 1, 1])")) ==
        "s.json: objects[0].shape.size[0]: expected a positive number up to 1e+09 (world units), "
        "got 1e+308");
  CHECK(errorOf(oneShape(R"("type": "sphere", "radius": 2e9)")) ==
        "s.json: objects[0].shape.radius: expected a positive number up to 1e+09 (world units), "
        "got 2000000000.0");
  // A mesh's vertices are held to the same range (the validator's tolerances overflowed near
  // 1e300: "height ... is -nan (tolerance inf)").
  {
    TempDir dir;
    std::ofstream(dir.path() / "far.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1e17\n"
                                             "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
    const std::string far = (dir.path() / "far.obj").string();
    CHECK_THAT(
        recode::core::test::sceneErrorOf(R"({"objects": [{"mesh": ")" + far + R"("}]})", "s.json"),
        Catch::Equals("s.json: objects[0].mesh: " + far +
                      ": vertex 3 (0, 0, 1e+17) has a coordinate outside -1e+09..1e+09 "
                      "(world units)"));
  }
  // The limits themselves are accepted.
  CHECK_NOTHROW(parseScene(
      oneObject(box + R"(, "position": [1e9, -1e9, 0], "motion": {"velocity": [1000, -1000, 0],
                "angular_velocity_deg": [1e6, -1e6, 1e6]}, "joint": {"axis": [0, 0, 1],
                "rate_deg": -1e6, "angle_deg": 1e6})"),
      "s.json", "."));
}

TEST_CASE("scene errors: resolution and pixel size", "[scene][errors]") {
  const auto withView = [](const std::string& view) {
    return errorOf(R"({"view": )" + view +
                   R"(, "objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}]})");
  };
  CHECK_THAT(withView(R"({"resolution": [0, 100]})"),
             StartsWith("s.json: view.resolution[0]: expected an integer in 1..16384, got 0"));
  CHECK_THAT(withView(R"({"resolution": [100, 16385]})"),
             StartsWith("s.json: view.resolution[1]: expected an integer in 1..16384, got 16385"));
  CHECK_THAT(withView(R"({"resolution": [100, -3]})"),
             StartsWith("s.json: view.resolution[1]: expected an integer in 1..16384, got -3"));
  CHECK_THAT(withView(R"({"resolution": [100, 18446744073709551615]})"),
             StartsWith("s.json: view.resolution[1]: expected an integer in 1..16384"));
  CHECK_THAT(withView(R"({"resolution": [100.5, 100]})"),
             StartsWith("s.json: view.resolution[0]: expected an integer in 1..16384, got 100.5"));
  CHECK_THAT(withView(R"({"resolution": [100]})"),
             StartsWith("s.json: view.resolution: expected an array of 2 integers [W, H], got 1 "
                        "element"));
  CHECK_THAT(withView(R"({"resolution": [100, 100], "pixel_size": 0.1})"),
             StartsWith("s.json: view.pixel_size: cannot be given together with \"resolution\""));
  CHECK_THAT(withView(R"({"pixel_size": 0})"),
             StartsWith("s.json: view.pixel_size: expected a positive number, got 0"));
  CHECK_THAT(withView(R"({"pixel_size": -0.5})"),
             StartsWith("s.json: view.pixel_size: expected a positive number, got -0.5"));
  CHECK(withView(R"({"pixel_size": 1e308})") ==
        "s.json: view.pixel_size: expected a positive number up to 1e+09 (world units), got "
        "1e+308");
}

TEST_CASE("scene errors: the objects list", "[scene][errors]") {
  CHECK_THAT(errorOf(R"({"view": {}})"), StartsWith("s.json: (root): missing key \"objects\""));
  CHECK_THAT(errorOf(R"({"objects": []})"),
             StartsWith("s.json: objects: expected at least one object, got an empty array"));
  CHECK_THAT(errorOf(oneObject(
                 R"("mesh": "meshes/octahedron.obj", "shape": {"type": "sphere", "radius": 1})")),
             StartsWith("s.json: objects[0]: give exactly one of \"mesh\", \"shape\", "
                        "\"children\" and \"part\", got \"mesh\" and \"shape\""));
  CHECK_THAT(errorOf(oneObject(R"("name": "nothing", "position": [0, 0, 0])")),
             StartsWith("s.json: objects[0]: missing \"mesh\", \"shape\", \"children\" or "
                        "\"part\""));
  CHECK_THAT(errorOf(R"({"objects": [{"mesh": "meshes/octahedron.obj"},
                                     {"name": "group", "children": []}]})"),
             StartsWith("s.json: objects[1].children: expected at least one child, got an empty "
                        "array"));
  CHECK_THAT(errorOf(oneObject(R"("name": "", "mesh": "meshes/octahedron.obj")")),
             StartsWith("s.json: objects[0].name: expected a non-empty string"));
}

TEST_CASE("scene errors: frames", "[scene][errors]") {
  const std::string objects = R"("objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}])";
  CHECK_THAT(errorOf(R"({"frames": 0, )" + objects + "}"),
             StartsWith("s.json: frames: expected an integer in 1..1000000, got 0"));
  CHECK_THAT(errorOf(R"({"frames": 2.5, )" + objects + "}"),
             StartsWith("s.json: frames: expected an integer in 1..1000000, got 2.5"));
  CHECK_THAT(errorOf(R"({"frames": "10", )" + objects + "}"),
             StartsWith("s.json: frames: expected an integer in 1..1000000, got a string"));
  CHECK(parse(R"({"frames": 1, )" + objects + "}").frames == 1);
  // The same cap as `recode run --frames`.
  CHECK(parse(R"({"frames": 1000000, )" + objects + "}").frames == 1000000);
  CHECK_THAT(errorOf(R"({"frames": 2147483647, )" + objects + "}"),
             StartsWith("s.json: frames: expected an integer in 1..1000000, got 2147483647"));
}

TEST_CASE("scene errors: shape types and sizes", "[scene][errors]") {
  CHECK_THAT(errorOf(oneShape(R"("type": "pyramid", "radius": 1)")),
             StartsWith("s.json: objects[0].shape.type: unknown shape type \"pyramid\" (expected "
                        "one of cone, cylinder, capped_cone, ellipsoid, sphere, box, torus)"));
  CHECK_THAT(errorOf(oneShape(R"("radius": 1)")),
             StartsWith("s.json: objects[0].shape: missing key \"type\""));
  CHECK_THAT(errorOf(oneShape(R"("type": "cone", "radius": -2, "height": 1)")),
             StartsWith("s.json: objects[0].shape.radius: expected a positive number, got -2"));
  CHECK_THAT(errorOf(oneShape(R"("type": "cylinder", "radius": 1, "height": 0)")),
             StartsWith("s.json: objects[0].shape.height: expected a positive number, got 0"));
  CHECK_THAT(errorOf(oneShape(R"("type": "cone", "radius": 1)")),
             StartsWith("s.json: objects[0].shape: missing key \"height\" for a cone shape"));
  CHECK_THAT(errorOf(oneShape(R"("type": "ellipsoid", "radii": [1, -1, 1])")),
             StartsWith("s.json: objects[0].shape.radii[1]: expected a positive number, got -1"));
  CHECK_THAT(errorOf(oneShape(R"("type": "ellipsoid", "radii": 1)")),
             StartsWith("s.json: objects[0].shape.radii: expected an array of 3 positive numbers"));
  CHECK_THAT(errorOf(oneShape(R"("type": "box", "size": [1, 1, 0])")),
             StartsWith("s.json: objects[0].shape.size[2]: expected a positive number, got 0"));
  CHECK_THAT(errorOf(oneShape(R"("type": "sphere", "radius": 1, "segments": 2)")),
             StartsWith("s.json: objects[0].shape.segments: expected an integer in 3..2147483647, "
                        "got 2"));
  CHECK_THAT(errorOf(oneShape(R"("type": "sphere", "radius": 1, "rings": 1)")),
             StartsWith("s.json: objects[0].shape.rings: expected an integer in 2..2147483647, "
                        "got 1"));
  CHECK_THAT(errorOf(oneShape(R"("type": "capped_cone", "radius0": 1, "radius1": 1, "height": 1,
                                  "rings": 0)")),
             StartsWith("s.json: objects[0].shape.rings: expected an integer in 1..2147483647"));
}

TEST_CASE("scene errors: a capped cone whose spheres nest", "[scene][errors]") {
  CHECK_THAT(errorOf(oneShape(R"("type": "capped_cone", "radius0": 2, "radius1": 0.5,
                                  "height": 1)")),
             StartsWith("s.json: objects[0].shape.height: must exceed |radius0 - radius1| = 1.5"));
  CHECK_THAT(errorOf(oneShape(R"("type": "capped_cone", "radius0": 0.5, "radius1": 2,
                                  "height": 1.5)")),
             StartsWith("s.json: objects[0].shape.height: must exceed"));
}

TEST_CASE("scene errors: generator limits are reported at the shape", "[scene][errors]") {
  // Too many triangles for one generator call: the scene's budget refuses it first, and with
  // the budget lifted, the generator's own message, at the shape.
  const std::string huge = oneShape(R"("type": "sphere", "radius": 1, "segments": 100000,
                                       "rings": 100000)");
  CHECK_THAT(errorOf(huge), StartsWith("s.json: objects[0].shape: this block would bring the "
                                       "scene to 19999800000 triangles"));
  try {
    (void)parseScene(huge, "s.json", ".", SceneReadLimits{SIZE_MAX});
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK_THAT(std::string(e.what()),
               StartsWith("s.json: objects[0].shape: ") && Contains("makeSphere"));
  }
}

TEST_CASE("scene errors: mesh files", "[scene][errors]") {
  TempDir dir;
  // A closed, outward octahedron whose top apex is pushed below the equator: a dent.
  (void)dir.write("dented.obj",
                  "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 -0.5\nv 0 0 -1\n"
                  "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
                  "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  (void)dir.write("broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  (void)dir.write("mesh.3mf", "solid x\nendsolid x\n");
  const auto errorIn = [&](const std::string& mesh) {
    try {
      (void)parseScene(R"({"objects": [{"shape": {"type": "box", "size": [1, 1, 1]}},
                                      {"mesh": ")" +
                           mesh + R"("}]})",
                       "s.json", dir.path());
    } catch (const SceneError& e) {
      CHECK(e.jsonPath() == "objects[1].mesh");
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string missing = errorIn("missing.obj");
  CHECK_THAT(missing, StartsWith("s.json: objects[1].mesh: "));
  CHECK_THAT(missing, Contains("missing.obj") && Contains("file not found"));
  const std::string dented = errorIn("dented.obj");
  CHECK_THAT(dented, StartsWith("s.json: objects[1].mesh: "));
  CHECK_THAT(dented, Contains("dented.obj") && Contains("convex"));
  CHECK_THAT(errorIn("broken.off"), StartsWith("s.json: objects[1].mesh: ") &&
                                        Contains("broken.off:6: ") && Contains("7"));
  CHECK_THAT(errorIn("mesh.3mf"),
             StartsWith("s.json: objects[1].mesh: ") && Contains("unknown mesh file extension"));
  CHECK_THAT(errorIn(""), StartsWith("s.json: objects[1].mesh: expected a non-empty string"));
}
