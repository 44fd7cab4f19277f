// Closed meshes in scene files: "closed": true on a mesh file and the torus shape make a leaf
// the layered pair decides; the errors name the JSON path and the rule.

#include <catch2/catch.hpp>
#include <string>

#include "recode/scene/scene.hpp"
#include "scene_test_support.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using recode::core::test::errorOf;
using recode::core::test::oneObject;
using recode::core::test::oneShape;
using recode::core::test::parse;
using recode::core::test::TempDir;

namespace {

// A closed, outward octahedron whose top apex is pushed below the equator: not convex, closed.
constexpr const char* kDented =
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 -0.5\nv 0 0 -1\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
    "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

}  // namespace

TEST_CASE("a torus shape is a closed mesh leaf", "[scene][closed]") {
  const Scene s = parse(oneShape(R"("type": "torus", "radius": 2, "tube_radius": 0.5)"));
  REQUIRE(s.objects.size() == 1);
  CHECK(s.objects[0].closed);
  CHECK(s.objects[0].localMesh.triangleCount() == 2u * 32u * 16u);  // the defaults
  const Scene box = parse(oneShape(R"("type": "box", "size": [1, 1, 1])"));
  CHECK_FALSE(box.objects[0].closed);
}

TEST_CASE("\"closed\": true takes a mesh file's faces as a closed mesh of any shape",
          "[scene][closed]") {
  TempDir dir;
  (void)dir.write("dented.obj", kDented);
  const Scene s =
      parseScene(R"({"objects": [{"mesh": "dented.obj", "closed": true}]})", "s.json", dir.path());
  CHECK(s.objects[0].closed);
  CHECK(s.objects[0].localMesh.triangleCount() == 8u);
  // Without it the same file is a convex block, and refused as one.
  CHECK_THROWS_WITH(parseScene(R"({"objects": [{"mesh": "dented.obj"}]})", "s.json", dir.path()),
                    Contains("not convex"));
}

TEST_CASE("closed-mesh errors name the path and the rule", "[scene][closed][errors]") {
  TempDir dir;
  (void)dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\n");
  CHECK_THAT(errorOf(oneObject(R"("shape": {"type": "box", "size": [1, 1, 1]}, "closed": true)")),
             StartsWith("s.json: objects[0].closed: ") &&
                 Contains("\"closed\" applies to a \"mesh\" only"));
  CHECK_THAT(errorOf(oneObject(R"("mesh": "x.obj", "closed": 1)")),
             StartsWith("s.json: objects[0].closed: ") && Contains("expected true or false"));
  CHECK_THAT(errorOf(oneObject(R"("mesh": "x.obj", "closed": true, "hull": true)")),
             StartsWith("s.json: objects[0].closed: ") &&
                 Contains("without \"hull\" or \"parts_from_groups\""));
  CHECK_THAT(errorOf(oneShape(R"("type": "torus", "radius": 1, "tube_radius": 1)")),
             StartsWith("s.json: objects[0].shape.tube_radius: ") &&
                 Contains("must be below radius (1) so that the hole stays open, got 1"));
  try {
    (void)parseScene(R"({"objects": [{"mesh": "open.obj", "closed": true}]})", "s.json",
                     dir.path());
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.jsonPath() == "objects[0].mesh");
    CHECK_THAT(e.what(), Contains("open.obj"));
  }
}

TEST_CASE("a closed mesh is refused where only convex blocks are decided", "[scene][closed]") {
  const Scene s = parse(R"({"objects": [{"shape": {"type": "sphere", "radius": 1}},
                                        {"name": "g", "children": [
                                          {"shape": {"type": "box", "size": [1, 1, 1]}},
                                          {"shape": {"type": "torus", "radius": 2,
                                                     "tube_radius": 0.5}}]}]})");
  CHECK_THROWS_WITH(requireConvexBlocks(s, "recode run"),
                    StartsWith("s.json: objects[1].children[1]: ") &&
                        Contains("is decided by `recode pair` alone; recode run takes convex"));
  CHECK_NOTHROW(requireConvexBlocks(parse(oneShape(R"("type": "sphere", "radius": 1)")), "x"));
}
