// A user's first program against the library: a scene given as JSON text (recode::scene), its
// two cones collided by RECODE on the CPU reference device (recode::pair, recode::raster), then
// again through the collision API (recode::api), which must agree on the verdict.
// Built by tests/package/installed (find_package) and tests/package/subdirectory
// (add_subdirectory); exits 0 when the cones' tips are found to interfere.
#include <cstdio>
#include <exception>

#include "recode/api/collision.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/scene/scene.hpp"

namespace {

// Two cones along z, tips overlapping by 0.2 (the built-in pair of `recode pair`).
constexpr const char* kScene = R"({
  "view": {"axis": "x", "resolution": [128, 128]},
  "objects": [
    {"shape": {"type": "cone", "radius": 1, "height": 2, "segments": 16},
     "position": [0, 0, -1.9]},
    {"shape": {"type": "cone", "radius": 1, "height": 2, "segments": 16},
     "position": [0, 0, 1.9], "rotation_deg": [180, 0, 0]}
  ]
})";

}  // namespace

int main() {
  using namespace recode;
  try {
    const core::Scene scene = core::parseScene(kScene, "consumer.json", ".");
    const core::TriangleMesh a = scene.objects[0].worldMesh();
    const core::TriangleMesh b = scene.objects[1].worldMesh();
    core::Aabb bounds = core::boundingBox(a);
    bounds.extend(core::boundingBox(b));
    core::PairRequest request;
    request.frame = core::resolveFrame(scene.view, bounds);
    raster::CpuDevice device(request.frame.width, request.frame.height);
    const core::PairResult result = core::collidePair(device, a, b, request);
    std::printf("collide: %s, interfering pixels: %lld\n", result.collide ? "yes" : "no",
                result.interferingPixels);
    // The same pair as objects: the API chooses its own frame.
    const recode::CollisionObject objectA(
        recode::CollisionGeometry::single(recode::ConvexBlock::fromMesh(a, "lower cone")));
    const recode::CollisionObject objectB(
        recode::CollisionGeometry::single(recode::ConvexBlock::fromMesh(b, "upper cone")));
    recode::CollisionResult api;
    recode::collide(objectA, objectB, recode::CollisionRequest{}, api);
    std::printf("api: collide: %s, interfering pixels: %lld\n", api.collide ? "yes" : "no",
                api.interferingPixels);
    return result.collide && result.interferingPixels > 0 && api.collide ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
}
