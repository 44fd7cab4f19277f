// Blocks from OBJ files: a cube and a tetrahedron (examples/data/) collided, then a dented cube
// whose convexity check fails when the block is made, with the library's message.
// Usage: obj_blocks [data folder] (default: this source tree's examples/data).
#include <cstdio>
#include <filesystem>
#include <string>

#include "recode/api/collision.hpp"
#include "recode/geometry/mesh_error.hpp"

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : RECODE_EXAMPLE_DATA_DIR;

  const recode::CollisionObject cube(
      recode::CollisionGeometry::single(recode::ConvexBlock::fromFile(data / "cube.obj")));
  // The tetrahedron's corner pushed 0.3 into the cube's far corner.
  const Eigen::Isometry3d moved(Eigen::Translation3d(0.7, 0.7, 0.7));
  const recode::CollisionObject tetra(
      recode::CollisionGeometry::single(recode::ConvexBlock::fromFile(data / "tetrahedron.obj")),
      moved);

  recode::CollisionRequest request;  // auto axis, 256 pixels across the overlap
  recode::CollisionResult result;
  recode::collide(cube, tetra, request, result);
  const std::string axis =
      result.collide ? std::string(recode::core::toString(result.contacts[0].frame.axis)) : "-";
  std::printf("cube and tetrahedron collide: %s (%lld pixels, viewed along %s)\n",
              result.collide ? "yes" : "no", result.interferingPixels, axis.c_str());

  // Every block is validated when made: a non-convex one never reaches collide().
  try {
    (void)recode::ConvexBlock::fromFile(data / "dented_cube.obj");
    std::printf("dented cube accepted\n");
    return 1;
  } catch (const recode::core::MeshError& e) {
    std::printf("dented cube rejected: %s\n", e.what());
  }
  return result.collide ? 0 : 1;
}
