// Scene files that are valid: every field parsed, defaults, poses, the example scenes in
// data/scenes. The errors are in scene_errors_test.cpp.

#include <catch2/catch.hpp>

#include <cmath>
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

namespace {

void checkSameMesh(const TriangleMesh& actual, const TriangleMesh& expected) {
  REQUIRE(actual.vertexCount() == expected.vertexCount());
  REQUIRE(actual.triangleCount() == expected.triangleCount());
  CHECK(actual.vertices == expected.vertices);
  CHECK(actual.triangles == expected.triangles);
}

}  // namespace

// ---- valid scenes ------------------------------------------------------------------------

TEST_CASE("scene: every shape type and mesh files parse with their values", "[scene]") {
  const Scene scene = parse(R"({
    "view": {"axis": "y", "window": [-4, -3.5, 4, 3.5], "resolution": [640, 480]},
    "frames": 12,
    "objects": [
      {"name": "cone", "shape": {"type": "cone", "radius": 1, "height": 2},
       "position": [1, 2, 3], "rotation_deg": [90, 0, -45],
       "motion": {"velocity": [0.5, 0, -0.25], "angular_velocity_deg": [0, 10, 0]}},
      {"name": "cylinder", "shape": {"type": "cylinder", "radius": 0.5, "height": 3,
                                     "segments": 12}},
      {"name": "capsule", "shape": {"type": "capped_cone", "radius0": 1, "radius1": 0.5,
                                    "height": 2, "segments": 16, "rings": 4}},
      {"name": "egg", "shape": {"type": "ellipsoid", "radii": [1, 2, 3]}},
      {"name": "ball", "shape": {"type": "sphere", "radius": 0.5, "segments": 8, "rings": 4},
       "motion": {}},
      {"name": "brick", "shape": {"type": "box", "size": [2, 4, 6]}},
      {"name": "octahedron", "mesh": "meshes/octahedron.obj"},
      {"mesh": "meshes/cube_quads.off"}
    ]})");

  CHECK(scene.sourceName == "s.json");
  CHECK(scene.view.axis == ViewAxis::Y);
  REQUIRE(scene.view.window.has_value());
  CHECK(scene.view.window->umin == -4.0);
  CHECK(scene.view.window->vmin == -3.5);
  CHECK(scene.view.window->umax == 4.0);
  CHECK(scene.view.window->vmax == 3.5);
  REQUIRE(scene.view.resolution.has_value());
  CHECK((*scene.view.resolution == std::array<int, 2>{640, 480}));
  CHECK_FALSE(scene.view.pixelSize.has_value());
  CHECK(scene.frames == 12);
  REQUIRE(scene.objects.size() == 8);

  const SceneObject& cone = scene.objects[0];
  CHECK(cone.name == "cone");
  CHECK(cone.jsonPath == "objects[0]");
  CHECK(cone.position == Eigen::Vector3d(1, 2, 3));
  CHECK(cone.rotationDeg == Eigen::Vector3d(90, 0, -45));
  REQUIRE(cone.motion.has_value());
  CHECK(cone.motion->velocity == Eigen::Vector3d(0.5, 0, -0.25));
  CHECK(cone.motion->angularVelocityDeg == Eigen::Vector3d(0, 10, 0));
  checkSameMesh(cone.localMesh, makeCone(1, 2, 32));

  CHECK(scene.objects[1].name == "cylinder");
  CHECK_FALSE(scene.objects[1].motion.has_value());
  checkSameMesh(scene.objects[1].localMesh, makeCylinder(0.5, 3, 12));
  checkSameMesh(scene.objects[2].localMesh, makeCappedCone(1, 0.5, 2, 16, 4));
  checkSameMesh(scene.objects[3].localMesh, makeEllipsoid(1, 2, 3, 32, 16));
  checkSameMesh(scene.objects[4].localMesh, makeSphere(0.5, 8, 4));
  REQUIRE(scene.objects[4].motion.has_value());  // "motion": {} is a motion of zero
  CHECK(scene.objects[4].motion->velocity == Eigen::Vector3d::Zero());
  CHECK(scene.objects[4].motion->angularVelocityDeg == Eigen::Vector3d::Zero());

  // "size" is the full edge lengths.
  const Aabb box = boundingBox(scene.objects[5].localMesh);
  CHECK(box.min == Eigen::Vector3d(-1, -2, -3));
  CHECK(box.max == Eigen::Vector3d(1, 2, 3));
  checkSameMesh(scene.objects[5].localMesh, makeBox(1, 2, 3));

  CHECK(scene.objects[6].name == "octahedron");
  checkSameMesh(scene.objects[6].localMesh, readObj(dataFile("meshes/octahedron.obj")));
  CHECK(scene.objects[7].name == "object 7");
  CHECK(scene.objects[7].jsonPath == "objects[7]");
  checkSameMesh(scene.objects[7].localMesh, readOff(dataFile("meshes/cube_quads.off")));
}

TEST_CASE("scene: defaults", "[scene]") {
  const Scene scene = parse(oneShape(R"("type": "sphere", "radius": 1)"));
  CHECK(scene.view.axis == ViewAxis::Z);
  CHECK_FALSE(scene.view.window.has_value());
  CHECK_FALSE(scene.view.resolution.has_value());
  CHECK_FALSE(scene.view.pixelSize.has_value());
  CHECK_FALSE(scene.frames.has_value());
  REQUIRE(scene.objects.size() == 1);
  const SceneObject& object = scene.objects[0];
  CHECK(object.name == "object 0");
  CHECK(object.position == Eigen::Vector3d::Zero());
  CHECK(object.rotationDeg == Eigen::Vector3d::Zero());
  CHECK_FALSE(object.motion.has_value());
  checkSameMesh(object.localMesh, makeSphere(1, 32, 16));
  CHECK(object.pose().matrix() == Eigen::Matrix4d::Identity());

  // Default segments and rings of the other round shapes.
  checkSameMesh(parse(oneShape(R"("type": "cone", "radius": 1, "height": 1)")).objects[0].localMesh,
                makeCone(1, 1, 32));
  checkSameMesh(
      parse(oneShape(R"("type": "cylinder", "radius": 1, "height": 1)")).objects[0].localMesh,
      makeCylinder(1, 1, 32));
  checkSameMesh(parse(oneShape(R"("type": "capped_cone", "radius0": 1, "radius1": 1, "height": 1)"))
                    .objects[0]
                    .localMesh,
                makeCappedCone(1, 1, 1, 32, 8));
  checkSameMesh(parse(oneShape(R"("type": "ellipsoid", "radii": [1, 1, 2])")).objects[0].localMesh,
                makeEllipsoid(1, 1, 2, 32, 16));

  // The view's own defaults: an empty view, and pixel_size instead of resolution.
  const Scene withPixelSize = parse(
      R"({"view": {"pixel_size": 0.01}, "objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}]})");
  CHECK(withPixelSize.view.axis == ViewAxis::Z);
  CHECK(withPixelSize.view.pixelSize == 0.01);
  CHECK_FALSE(withPixelSize.view.resolution.has_value());
  CHECK(parse(R"({"view": {}, "objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}]})")
            .view.axis == ViewAxis::Z);
  CHECK(
      parse(
          R"({"view": {"axis": "x"}, "objects": [{"shape": {"type": "box", "size": [1, 1, 1]}}]})")
          .view.axis == ViewAxis::X);
}

// ---- rotation and pose -------------------------------------------------------------------

TEST_CASE("rotationFromDegrees: quarter turns are exact", "[scene]") {
  CHECK(rotationFromDegrees({0, 0, 0}) == Eigen::Matrix3d::Identity());
  // About X: y -> z; about Y: z -> x; about Z: x -> y.
  CHECK(rotationFromDegrees({90, 0, 0}) * Eigen::Vector3d(0, 1, 0) == Eigen::Vector3d(0, 0, 1));
  CHECK(rotationFromDegrees({0, 90, 0}) * Eigen::Vector3d(0, 0, 1) == Eigen::Vector3d(1, 0, 0));
  CHECK(rotationFromDegrees({0, 0, 90}) * Eigen::Vector3d(1, 0, 0) == Eigen::Vector3d(0, 1, 0));
  CHECK(rotationFromDegrees({180, 0, 0}) * Eigen::Vector3d(1, 2, 3) == Eigen::Vector3d(1, -2, -3));
  CHECK(rotationFromDegrees({0, -90, 0}) * Eigen::Vector3d(0, 0, 1) == Eigen::Vector3d(-1, 0, 0));
  // Whole turns and multiples beyond one turn reduce exactly.
  CHECK(rotationFromDegrees({360, -720, 1080}) == Eigen::Matrix3d::Identity());
  CHECK(rotationFromDegrees({450, 0, 0}) == rotationFromDegrees({90, 0, 0}));
  CHECK(rotationFromDegrees({-270, 0, 0}) == rotationFromDegrees({90, 0, 0}));
  // Every entry of a quarter-turn rotation is exactly 0 or +-1.
  const Eigen::Matrix3d r = rotationFromDegrees({90, 270, -180});
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double e = r(i, j);
      CHECK((e == 0.0 || e == 1.0 || e == -1.0));
    }
  }
}

TEST_CASE("rotationFromDegrees: X first, then Y, then Z", "[scene]") {
  // (0, 1, 0) about X by 90 -> (0, 0, 1), about Y by 90 -> (1, 0, 0), about Z by 90 ->
  // (0, 1, 0). In the opposite order (Z, Y, X) it would end at (0, 0, 1).
  CHECK(rotationFromDegrees({90, 90, 0}) * Eigen::Vector3d(0, 1, 0) == Eigen::Vector3d(1, 0, 0));
  CHECK(rotationFromDegrees({90, 90, 90}) * Eigen::Vector3d(0, 1, 0) == Eigen::Vector3d(0, 1, 0));
  // (1, 2, 3): X 90 -> (1, -3, 2); Y 90 -> (2, -3, -1); Z 90 -> (3, 2, -1).
  CHECK(rotationFromDegrees({90, 90, 90}) * Eigen::Vector3d(1, 2, 3) == Eigen::Vector3d(3, 2, -1));

  // General angles: Rz * Ry * Rx, as Eigen's angle-axis rotations compose.
  const Eigen::Vector3d degrees(30, -50, 110);
  const double k = std::numbers::pi / 180.0;
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(degrees.z() * k, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(degrees.y() * k, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(degrees.x() * k, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  const Eigen::Matrix3d r = rotationFromDegrees(degrees);
  CHECK((r - expected).cwiseAbs().maxCoeff() < 1e-15);
  CHECK((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-15);
  CHECK(r.determinant() == Approx(1.0).epsilon(1e-15));
  CHECK(rotationFromDegrees({30, 0, 0})(2, 1) == std::sin(30 * k));
}

TEST_CASE("scene: pose and world mesh", "[scene]") {
  const Scene scene = parse(oneObject(
      R"("shape": {"type": "cone", "radius": 1, "height": 2}, "position": [0.5, -1, 3.75],
         "rotation_deg": [180, 0, 0])"));
  const SceneObject& cone = scene.objects[0];
  const Eigen::Isometry3d pose = cone.pose();
  CHECK(pose.linear() == rotationFromDegrees({180, 0, 0}));
  CHECK(pose.translation() == Eigen::Vector3d(0.5, -1, 3.75));

  const TriangleMesh world = cone.worldMesh();
  REQUIRE(world.vertexCount() == cone.localMesh.vertexCount());
  CHECK(world.triangles == cone.localMesh.triangles);  // a rotation keeps the winding
  for (std::size_t i = 0; i < world.vertexCount(); ++i) {
    const Eigen::Vector3d& p = cone.localMesh.vertices[i];
    CHECK(world.vertices[i] == Eigen::Vector3d(p.x() + 0.5, -p.y() - 1, 3.75 - p.z()));
  }
  // The apex (last vertex) turned downward: exactly 3.75 - 2.
  CHECK(world.vertices.back() == Eigen::Vector3d(0.5, -1, 1.75));
  CHECK(signedVolume(world) > 0.0);
}

// ---- files -------------------------------------------------------------------------------

TEST_CASE("loadScene: mesh paths are relative to the scene file", "[scene]") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "scenes" / "meshes");
  (void)dir.write("scenes/meshes/tet.obj",
                  "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 2 1 4\nf 3 2 4\nf 1 3 4\n");
  const auto file =
      dir.write("scenes/scene.json",
                R"({"objects": [{"name": "t", "mesh": "meshes/tet.obj"}, {"mesh": "meshes/tet.obj",
          "position": [3, 0, 0]}]})");
  const Scene scene = loadScene(file);
  CHECK(scene.sourceName == file.string());
  REQUIRE(scene.objects.size() == 2);
  CHECK(scene.objects[0].localMesh.vertexCount() == 4);
  CHECK(scene.objects[1].worldMesh().vertices[0] == Eigen::Vector3d(4, 1, 1));
}

TEST_CASE("loadScene: the example scenes in data/scenes", "[scene]") {
  const Scene cones = loadScene(dataFile("scenes/cones-tip-to-tip.json"));
  CHECK(cones.view.axis == ViewAxis::X);
  CHECK_FALSE(cones.view.window.has_value());
  CHECK((cones.view.resolution == std::array<int, 2>{256, 256}));
  REQUIRE(cones.objects.size() == 2);
  const TriangleMesh a = cones.objects[0].worldMesh();
  const TriangleMesh b = cones.objects[1].worldMesh();
  // A's apex at z = 2, B's (turned upside down) 0.25 below it; bases at z = 0 and 3.75.
  CHECK(a.vertices.back() == Eigen::Vector3d(0, 0, 2));
  CHECK(b.vertices.back() == Eigen::Vector3d(0, 0, 1.75));
  CHECK(boundingBox(a).min.z() == 0.0);
  CHECK(boundingBox(b).max.z() == 3.75);

  const Scene boxes = loadScene(dataFile("scenes/box-on-box.json"));
  CHECK(boxes.view.axis == ViewAxis::Z);
  REQUIRE(boxes.objects.size() == 2);
  // Face on face: the top of the lower box is the bottom of the upper one.
  CHECK(boundingBox(boxes.objects[0].worldMesh()).max.z() ==
        boundingBox(boxes.objects[1].worldMesh()).min.z());
}

TEST_CASE("loadScene: a missing or unreadable scene file", "[scene][errors]") {
  TempDir dir;
  const std::string missing = (dir.path() / "nope.json").string();
  try {
    (void)loadScene(missing);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK_THAT(e.what(), StartsWith(missing + ": "));
    CHECK_THAT(e.what(), Contains("cannot read scene file: file not found"));
    CHECK(e.file() == missing);
    CHECK(e.jsonPath().empty());
  }
  CHECK_THROWS_WITH(loadScene(dir.path()), Contains("cannot read scene file: it is a directory"));
  // Not a regular file: refused before a byte is read (reading /dev/zero would never end).
  CHECK_THROWS_WITH(loadScene("/dev/zero"),
                    Catch::Equals("/dev/zero: cannot read scene file: it is not a regular file "
                                  "(a character device)"));
}
