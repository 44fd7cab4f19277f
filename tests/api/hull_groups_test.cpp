// Blocks from point sets and from multi-group OBJ files through the collision API: the plate-like
// mesh (refused as it is, accepted as a hull), the L of three convex pieces as one object with a
// block per piece, and their errors. Contacts are checked against where the pieces are by
// construction (data/meshes/l_shape_parts.obj's comment), not against a run.

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/validate.hpp"

namespace {

using namespace recode;

std::filesystem::path meshFile(const std::string& name) {
  return std::filesystem::path(RECODE_DATA_DIR) / "meshes" / name;
}

TEST_CASE("fromHull makes a block of the extreme points; degenerate sets are refused") {
  // A cube's corners, its centre and its face centres: the hull is the cube.
  std::vector<Eigen::Vector3d> points{Eigen::Vector3d::Zero()};
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  for (int axis = 0; axis < 3; ++axis) {
    points.push_back(Eigen::Vector3d::Unit(axis));
    points.push_back(-Eigen::Vector3d::Unit(axis));
  }
  const ConvexBlockPtr cube = ConvexBlock::fromHull(points, "cube");
  CHECK(cube->name() == "cube");
  CHECK(cube->mesh().vertexCount() == 8);
  CHECK(core::signedVolume(cube->mesh()) == Approx(8.0).epsilon(1e-14));

  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  CHECK_THROWS_WITH(ConvexBlock::fromHull(line, "stick"),
                    "stick: convex hull: all 4 points lie on one line (a convex hull needs at "
                    "least 4 points that do not lie in one plane)");
}

TEST_CASE("a plate-like file is refused as a mesh with a hint, and accepted as a hull") {
  const std::filesystem::path plate = meshFile("plate_like.obj");
  CHECK_THROWS_WITH(ConvexBlock::fromFile(plate),
                    Catch::Contains("edge (1, 2) is used by 3 triangles") &&
                        Catch::EndsWith("(to use the convex hull of its vertices instead, use "
                                        "ConvexBlock::fromFileHull)"));
  const ConvexBlockPtr block = ConvexBlock::fromFileHull(plate);
  CHECK(block->name() == plate.string());
  CHECK(block->mesh().vertexCount() == 8);
  // The outline's frustum: h/3 (A1 + A2 + sqrt(A1 A2)) with sides 2 and 1.2, height 0.15.
  CHECK(core::signedVolume(block->mesh()) == Approx(0.05 * 7.84).epsilon(1e-12));
}

TEST_CASE("a multi-group OBJ is one object with a block per group, in contact by block") {
  for (const bool hull : {false, true}) {
    INFO("hull " << hull);
    const std::filesystem::path file = meshFile("l_shape_parts.obj");
    const CollisionGeometryPtr l = CollisionGeometry::fromObjGroups(file, hull);
    REQUIRE(l->blockCount() == 3);
    CHECK(l->part(2).block->name() == file.string() + ": group 'convex_2'");
    const CollisionObject object(l);
    // A small cube at (2.5, 0.5, 0.5) lies in the foot (convex_1, block 1) only; at
    // (2.5, 2.5, 0.5) it is in the L's notch, touching nothing.
    const CollisionGeometryPtr probeShape =
        CollisionGeometry::single(ConvexBlock::fromMesh(core::makeBox(0.2, 0.2, 0.2), "probe"));
    CollisionRequest request;
    request.pixelSize = 0.01;
    CollisionResult result;
    const CollisionObject inFoot(probeShape,
                                 Eigen::Isometry3d(Eigen::Translation3d(2.5, 0.5, 0.5)));
    REQUIRE(collide(object, inFoot, request, result));
    REQUIRE(result.contacts.size() == 1);
    CHECK(result.contacts[0].blockA == 1);
    const CollisionObject inNotch(probeShape,
                                  Eigen::Isometry3d(Eigen::Translation3d(2.5, 2.5, 0.5)));
    CHECK_FALSE(collide(object, inNotch, request, result));
  }
  CHECK_THROWS_WITH(CollisionGeometry::fromObjGroups(meshFile("octahedron.off")),
                    Catch::Contains("only an OBJ file has groups"));
}

}  // namespace
