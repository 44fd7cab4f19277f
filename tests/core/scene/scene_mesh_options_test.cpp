// "hull" and "parts_from_groups" on a scene's mesh entry: collision meshes that are convex in
// shape but not clean closed surfaces (data/meshes/plate_like.obj: an edge used by three
// triangles), and convex decompositions written as OBJ groups (data/meshes/l_shape_parts.obj:
// three boxes of an L). Expected volumes come from the shapes' construction, not from a run.

#include <catch2/catch.hpp>

#include <string>

#include "recode/geometry/validate.hpp"
#include "scene_test_support.hpp"

namespace recode::core {
namespace {

using Catch::Contains;
using Catch::EndsWith;
using Catch::StartsWith;
using test::errorOf;
using test::oneObject;
using test::parse;
using test::TempDir;

const std::string kHint = " (to use the convex hull of its vertices instead, give \"hull\": true)";

TEST_CASE("a plate-like collision mesh is refused with a hint, and hulled with \"hull\"",
          "[scene][hull]") {
  const std::string refused = errorOf(oneObject(R"("mesh": "meshes/plate_like.obj")"));
  CHECK_THAT(refused, StartsWith("s.json: objects[0].mesh: ") &&
                          Contains("plate_like.obj: edge (1, 2) is used by 3 triangles") &&
                          EndsWith(kHint));

  const Scene scene = parse(oneObject(R"("mesh": "meshes/plate_like.obj", "hull": true)"));
  const TriangleMesh& plate = scene.objects.at(0).localMesh;
  CHECK(checkConvexBlock(plate).ok());
  // The hull is the outline, a frustum of squares: sides 2 (top) and 1.2 (bottom), height
  // 0.15, so volume h/3 (A1 + A2 + sqrt(A1 A2)) = 0.05 (4 + 1.44 + 2.4); 6 quads, 12 triangles.
  CHECK(plate.vertexCount() == 8);
  CHECK(plate.triangleCount() == 12);
  CHECK(signedVolume(plate) == Approx(0.05 * 7.84).epsilon(1e-12));
  // "hull": false is the same as leaving it out.
  CHECK_THAT(errorOf(oneObject(R"("mesh": "meshes/plate_like.obj", "hull": false)")),
             EndsWith(kHint));
}

TEST_CASE("a multi-group OBJ is one object with a block per group", "[scene][groups]") {
  for (const char* hull : {"", R"(, "hull": true)"}) {
    INFO("extra keys: " << hull);
    const Scene scene = parse(
        oneObject(R"("name": "L", "mesh": "meshes/l_shape_parts.obj", "parts_from_groups": true)" +
                  std::string(hull) + R"(, "position": [5, 0, 0])"));
    const SceneObject& l = scene.objects.at(0);
    CHECK(l.name == "L");
    CHECK(l.position.x() == 5.0);
    REQUIRE(l.children.size() == 3);
    const double volumes[] = {1.0, 2.0, 2.0};  // the boxes of the file's comment
    for (std::size_t k = 0; k < 3; ++k) {
      const SceneObject& piece = l.children[k];
      CHECK(piece.name == "convex_" + std::to_string(k));
      CHECK(piece.isLeaf());
      CHECK(piece.jsonPath == "objects[0].mesh.convex_" + std::to_string(k));
      CHECK(checkConvexBlock(piece.localMesh).ok());
      CHECK(piece.localMesh.vertexCount() == 8);
      CHECK(signedVolume(piece.localMesh) == Approx(volumes[k]).epsilon(1e-12));
    }
  }
}

TEST_CASE("a multi-group OBJ as one mesh: refused, or its hull as one block", "[scene][groups]") {
  // Three separate boxes are not one closed surface.
  CHECK_THAT(errorOf(oneObject(R"("mesh": "meshes/l_shape_parts.obj")")),
             Contains("the mesh has 3 connected components") && EndsWith(kHint));
  // The hull of all 24 points: the L's outline (0,0) (3,0) (3,1) (1,3) (0,3), area 7, height 1.
  const Scene scene = parse(oneObject(R"("mesh": "meshes/l_shape_parts.obj", "hull": true)"));
  CHECK(signedVolume(scene.objects.at(0).localMesh) == Approx(7.0).epsilon(1e-12));
  CHECK(scene.objects.at(0).localMesh.vertexCount() == 10);
}

TEST_CASE("errors of a multi-group OBJ name the group", "[scene][groups]") {
  TempDir dir;
  // Group "good" is a tetrahedron; group "dented" an octahedron with a dent (not convex); group
  // "flat" four points in one plane.
  (void)dir.write("parts.obj",
                  "o good\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                  "o dented\nv 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 -0.5\nv 0 0 -1\n"
                  "f 5 7 9\nf 7 6 9\nf 6 8 9\nf 8 5 9\n"
                  "f 7 5 10\nf 6 7 10\nf 8 6 10\nf 5 8 10\n");
  (void)dir.write("flat.obj", "o flat\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\n");
  (void)dir.write("box.off",
                  "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                  "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const auto errorIn = [&](const std::string& members) {
    try {
      (void)parseScene(R"({"objects": [{)" + members + "}]}", "s.json", dir.path());
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string dented = errorIn(R"("mesh": "parts.obj", "parts_from_groups": true)");
  CHECK_THAT(dented, StartsWith("s.json: objects[0].mesh: ") &&
                         Contains("parts.obj: group 'dented': vertex ") &&
                         Contains("the mesh is not convex") && EndsWith(kHint));
  CHECK_THAT(errorIn(R"("mesh": "flat.obj", "parts_from_groups": true, "hull": true)"),
             StartsWith("s.json: objects[0].mesh: ") &&
                 Contains("flat.obj: group 'flat': convex hull: all 4 points lie in one plane "
                          "(a convex hull needs at least 4 points that do not lie in one plane)"));
  CHECK_THAT(errorIn(R"("mesh": "flat.obj", "hull": true)"),
             Contains("flat.obj: convex hull: all 4 points lie in one plane"));
  CHECK_THAT(errorIn(R"("mesh": "box.off", "parts_from_groups": true)"),
             StartsWith("s.json: objects[0].mesh: ") &&
                 Contains("box.off: only an OBJ file has groups (\"parts_from_groups\" needs a "
                          ".obj file)"));
  CHECK(errorIn(R"("mesh": "box.off", "hull": true)").empty());  // an OFF file hulls too
}

TEST_CASE("\"hull\" and \"parts_from_groups\" belong to a mesh and are booleans", "[scene][hull]") {
  const std::string box = R"("shape": {"type": "box", "size": [1, 1, 1]})";
  CHECK(errorOf(oneObject(box + R"(, "hull": true)")) ==
        "s.json: objects[0].hull: \"hull\" applies to a \"mesh\" only");
  CHECK(errorOf(oneObject(box + R"(, "parts_from_groups": true)")) ==
        "s.json: objects[0].parts_from_groups: \"parts_from_groups\" applies to a \"mesh\" only");
  CHECK(errorOf(oneObject(R"("mesh": "meshes/octahedron.obj", "hull": 1)")) ==
        "s.json: objects[0].hull: expected true or false, got 1");
  CHECK(errorOf(R"({"parts": {"p": {"shape": {"type": "box", "size": [1, 1, 1]}}},
                   "objects": [{"part": "p", "hull": true}]})") ==
        "s.json: objects[0].hull: \"hull\" applies to a \"mesh\" only");
  // In a part, next to its mesh, both work.
  const Scene scene = parse(R"({"parts": {"plate": {"mesh": "meshes/plate_like.obj", "hull": true},
                                          "L": {"mesh": "meshes/l_shape_parts.obj",
                                                "parts_from_groups": true}},
                               "objects": [{"part": "plate"}, {"part": "L"}]})");
  CHECK(scene.objects.at(0).localMesh.vertexCount() == 8);
  CHECK(scene.objects.at(1).children.size() == 3);
}

}  // namespace
}  // namespace recode::core
