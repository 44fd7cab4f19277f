// The pair algorithm on the CPU device: the built-in pair (two cones tip to tip) at several
// resolutions and the three MOR variants. Reports the mean time of every step and the
// pixels read as counters, so a run answers "where does a pair's time go".
//
//   build/bench/recode_pair_bench --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <array>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/refine/block_growth.hpp"
#include "recode/scene/builtin_scenes.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"

namespace {

using namespace recode;

// The mean time of each step of the pairs a benchmark ran, as counters named after the steps.
class StepTimes {
 public:
  void add(const core::PairResult& result) {
    for (std::size_t s = 0; s < stepUs_.size(); ++s)
      stepUs_[s] += result.timing.stepUs[s];
    classifyUs_ += result.timing.classifyUs;
  }
  void report(benchmark::State& state) const {
    const double n = static_cast<double>(state.iterations());
    for (std::size_t s = 0; s < stepUs_.size(); ++s)
      state.counters[std::string(core::toString(static_cast<core::PairStep>(s))) + "_us"] =
          stepUs_[s] / n;
    state.counters["classify_us"] = classifyUs_ / n;
  }

 private:
  std::array<double, core::kPairStepCount> stepUs_{};
  double classifyUs_ = 0.0;
};

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
  StepTimes steps;
  core::PairResult last;
  for (auto _ : state) {
    last = core::collidePair(device, a, b, request);
    steps.add(last);
    benchmark::DoNotOptimize(last.collide);
  }
  steps.report(state);
  state.counters["stencil_px"] = static_cast<double>(last.stencilPixelsRead);
  state.counters["depth_px"] = static_cast<double>(last.depthPixelsRead);
  state.counters["interfering_px"] = static_cast<double>(last.interferingPixels);
  state.SetLabel(std::string("mor ") + std::string(core::toString(mor)));
}

BENCHMARK(pairBench)
    ->ArgsProduct({{64, 256, 1024}, {0, 1, 2}})
    ->ArgNames({"res", "mor"})
    ->Unit(benchmark::kMicrosecond);

// Two touching spheres with a thin MOR (docs/benchmarks.md, "A pair's cost and its meshes"):
// radius 1, centres 1.98 apart along x, seen along z at 512x512 with the default window, MIN
// MOR, contact passes on. `segments` x `rings` sets the triangles per block: 32 x 16 gives 960,
// 1024 x 512 gives 1,046,528. hierarchy = 1 hands collidePair blocks with their triangle
// hierarchies (built before the timed loop, as a run keeps them), 0 the bare meshes (every
// triangle drawn, as before the hierarchies). The steps' mean times are counters, as above:
// set_z holds the hierarchy queries and the first draws, the later steps replay their draws.
void thinMorSpheres(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const bool hierarchy = state.range(1) != 0;
  const int rings = segments / 2;
  const core::TriangleMesh a = core::makeSphere(1.0, segments, rings);
  core::TriangleMesh b = a;
  for (Eigen::Vector3d& p : b.vertices)
    p.x() += 1.98;
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::PairRequest request;
  request.frame = core::resolveFrame(core::ViewSpec{}, bounds, {512, 512, {}});
  const core::PairBlock blockA = hierarchy ? core::PairBlock::withHierarchy(a) : core::PairBlock(a);
  const core::PairBlock blockB = hierarchy ? core::PairBlock::withHierarchy(b) : core::PairBlock(b);
  raster::CpuDevice device(512, 512);
  StepTimes steps;
  core::PairResult last;
  for (auto _ : state) {
    last = core::collidePair(device, blockA, blockB, request);
    steps.add(last);
    benchmark::DoNotOptimize(last.collide);
  }
  steps.report(state);
  state.counters["triangles_drawn"] = static_cast<double>(device.counters().trianglesSubmitted) /
                                      static_cast<double>(state.iterations());
  state.counters["triangles_per_block"] = static_cast<double>(a.triangleCount());
  state.counters["mor_px"] = static_cast<double>(last.mor.area());
  state.counters["interfering_px"] = static_cast<double>(last.interferingPixels);
}

BENCHMARK(thinMorSpheres)
    ->ArgsProduct({{32, 1024}, {0, 1}})
    ->ArgNames({"segments", "hierarchy"})
    ->Unit(benchmark::kMicrosecond);

// The pairs that cost the hands' frames: a fingertip touching the ball in hand-grasp at
// 2,304 triangles per block, frame 69 (every finger touches), drawn as a run draws it (world
// meshes with their triangle hierarchies, the run's pair frame): the fingertip lies wholly
// inside the MOR. Step times as in pairBench.
void fingertipOnBall(benchmark::State& state) {
  const core::Scene scene = core::builtinExperimentScene("hand-grasp", 2304);
  core::Simulation sim(scene, core::RunOptions{});
  static_cast<void>(sim.runFrame(69));
  sim.updateAllBounds();
  const auto leaf = [&](std::size_t object, const std::string& path) {
    const core::ObjectTree& tree = sim.objects()[object];
    for (const int n : tree.leaves())
      if (tree.nodes()[static_cast<std::size_t>(n)].path == path)
        return n;
    throw std::invalid_argument("no leaf " + path);
  };
  const core::ObjectTree& hand = sim.objects()[0];
  const core::ObjectTree& ball = sim.objects()[2];
  const int tip = leaf(0, "left hand/thumb/proximal/middle/distal");
  const int whole = leaf(2, "ball");
  const core::TriangleMesh tipMesh = hand.worldMesh(tip), ballMesh = ball.worldMesh(whole);
  const core::HierarchyNode& tipNode = hand.nodes()[static_cast<std::size_t>(tip)];
  const core::HierarchyNode& ballNode = ball.nodes()[static_cast<std::size_t>(whole)];
  const core::PairBlock a(tipMesh, hand.triangleHierarchy(tip), tipNode.world);
  const core::PairBlock b(ballMesh, ball.triangleHierarchy(whole), ballNode.world);
  core::PairRequest request;
  request.frame = sim.leafPairFrame(tipNode, ballNode);
  raster::CpuDevice device(request.frame.width, request.frame.height);
  StepTimes steps;
  core::PairResult last;
  for (auto _ : state) {
    last = core::collidePair(device, a, b, request);
    steps.add(last);
    benchmark::DoNotOptimize(last.collide);
  }
  steps.report(state);
  const double n = static_cast<double>(state.iterations());
  state.counters["triangles_drawn"] = static_cast<double>(device.counters().trianglesSubmitted) / n;
  state.counters["fragments"] = static_cast<double>(device.counters().fragments) / n;
  state.counters["mor_px"] = static_cast<double>(last.mor.area());
  state.counters["interfering_px"] = static_cast<double>(last.interferingPixels);
}

BENCHMARK(fingertipOnBall)->Unit(benchmark::kMicrosecond);

// Building one block's triangle hierarchy (once per block, outside the pair tests).
void triangleHierarchyBuild(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const core::TriangleMesh a = core::makeSphere(1.0, segments, segments / 2);
  for (auto _ : state) {
    const core::TriangleBvh bvh(a);
    benchmark::DoNotOptimize(bvh.nodeCount());
  }
  state.counters["triangles"] = static_cast<double>(a.triangleCount());
}

BENCHMARK(triangleHierarchyBuild)
    ->Arg(32)
    ->Arg(1024)
    ->ArgName("segments")
    ->Unit(benchmark::kMillisecond);

// Growing one block by a box (three sweeps): what the conservative mode does to both blocks of
// every pair test, and the adaptive mode to both whole blocks at every refined tile.
void blockGrowth(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const core::TriangleMesh a = core::makeSphere(1.0, segments, segments / 2);
  const Eigen::Vector3d half(0.01, 0.02, 0.005);
  for (auto _ : state) {
    const core::TriangleMesh grown = core::grownByBox(a, half);
    benchmark::DoNotOptimize(grown.triangles.data());
  }
  state.counters["triangles"] = static_cast<double>(a.triangleCount());
}

BENCHMARK(blockGrowth)->Arg(32)->Arg(152)->ArgName("segments")->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
