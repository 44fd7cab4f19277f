// The collision API per pair (docs/api.md#cost): recode::collide on the built-in pair of
// `recode pair` (two cones tip to tip, viewed along x with its pixel size), and on one pair of
// the generated suite, auto axis at 256 pixels (the default) and 64. Measured around the call, as a
// user pays it (clearing and filling the result included); collision_us is the API's own timing.
//
//   build/bench/recode_api_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include "recode/api/collision.hpp"
#include "recode/scene/builtin_scenes.hpp"
#include "recode/verify/pair_suite.hpp"

namespace {

using namespace recode;

CollisionObject objectOf(const core::TriangleMesh& mesh) {
  return CollisionObject(CollisionGeometry::single(ConvexBlock::fromMesh(mesh, "block")));
}

void run(benchmark::State& state, const CollisionObject& a, const CollisionObject& b,
         const CollisionRequest& request) {
  CollisionResult result;
  double collisionUs = 0.0;
  for (auto _ : state) {
    collide(a, b, request, result);
    collisionUs += result.collisionUs;
    benchmark::DoNotOptimize(result.collide);
  }
  state.counters["collision_us"] = collisionUs / static_cast<double>(state.iterations());
  state.counters["interfering_px"] = static_cast<double>(result.interferingPixels);
}

// The built-in pair in world coordinates, along x at the pixel size of its 256-pixel frame.
void builtinPair(benchmark::State& state) {
  const core::Scene scene = core::builtinPairScene();
  const core::TriangleMesh a = scene.objects[0].worldMesh(), b = scene.objects[1].worldMesh();
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  const core::FrameSpec frame = core::resolveFrame(scene.view, bounds);
  CollisionRequest request;
  request.axis = AxisChoice::X;
  request.pixelSize = (frame.window.umax - frame.window.umin) / frame.width;
  run(state, objectOf(a), objectOf(b), request);
}
BENCHMARK(builtinPair)->Unit(benchmark::kMicrosecond);

// Pair `index` of the generated suite (504 pairs), auto axis at `resolution` pixels over the
// overlap (256: the API's default).
void suitePair(benchmark::State& state) {
  const verify::SuitePair p = verify::generatePairSuite()[static_cast<std::size_t>(state.range(0))];
  state.SetLabel(p.label);
  CollisionRequest request;
  request.resolution = static_cast<int>(state.range(1));
  run(state, objectOf(p.a), objectOf(p.b), request);
}
BENCHMARK(suitePair)
    ->ArgsProduct({{28}, {256, 64}})
    ->ArgNames({"pair", "res"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
