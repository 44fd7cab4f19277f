// The pair algorithm on the CPU device: the built-in pair (two cones tip to tip) at several
// resolutions and the three MOR variants. Reports the mean time of every step and the
// pixels read as counters, so a run answers "where does a pair's time go".
//
//   build/bench/recode_pair_bench --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <array>

#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/scene/builtin_scenes.hpp"

namespace {

using namespace recode;

void pairBench(benchmark::State& state) {
  const int resolution = static_cast<int>(state.range(0));
  const auto mor = static_cast<core::MorMode>(state.range(1));
  const core::Scene scene = core::builtinPairScene();
  const core::TriangleMesh a = scene.objects[0].worldMesh(), b = scene.objects[1].worldMesh();
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::PairRequest request;
  request.frame = core::resolveFrame(scene.view, bounds, {resolution, resolution, {}});
  request.mor = mor;
  raster::CpuDevice device(resolution, resolution);
  std::array<double, core::kPairStepCount> stepUs{};
  double classifyUs = 0.0;
  core::PairResult last;
  for (auto _ : state) {
    last = core::collidePair(device, a, b, request);
    for (std::size_t s = 0; s < stepUs.size(); ++s)
      stepUs[s] += last.timing.stepUs[s];
    classifyUs += last.timing.classifyUs;
    benchmark::DoNotOptimize(last.collide);
  }
  const double n = static_cast<double>(state.iterations());
  for (std::size_t s = 0; s < stepUs.size(); ++s)
    state.counters[std::string(core::toString(static_cast<core::PairStep>(s))) + "_us"] =
        stepUs[s] / n;
  state.counters["classify_us"] = classifyUs / n;
  state.counters["stencil_px"] = static_cast<double>(last.stencilPixelsRead);
  state.counters["depth_px"] = static_cast<double>(last.depthPixelsRead);
  state.counters["interfering_px"] = static_cast<double>(last.interferingPixels);
  state.SetLabel(std::string("mor ") + std::string(core::toString(mor)));
}

BENCHMARK(pairBench)
    ->ArgsProduct({{64, 256, 1024}, {0, 1, 2}})
    ->ArgNames({"res", "mor"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
