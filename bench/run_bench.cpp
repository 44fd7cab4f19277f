// Whole frames of `recode run` on the CPU device with 1, 2 and all threads for the pair tests
// (core::RunOptions::threads): the frames of random-cones and of hand-grasp, one frame per
// iteration in turn, wall clock (UseRealTime), as a user waits for them. The largest levels
// of the hands and the aligned translation (issue 14's targets against fcl-gjk) run on one
// thread in both the reference and the skip-apart mode, for profiling a frame loop without
// the scene's making (`perf record` over a long --benchmark_min_time).
//
//   build/bench/recode_run_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>

#include <string>

#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"

namespace {

using namespace recode;

void runFramesOf(benchmark::State& state, const core::Scene& scene, core::RunOptions options) {
  core::Simulation sim(scene, options);
  const int frames = scene.frames.value_or(core::kDefaultRunFrames);
  for (int k = 0; k < frames; ++k)
    (void)sim.runFrame(k);  // every device made and every page touched before timing
  int k = 0;
  long long pairTests = 0;
  for (auto _ : state) {
    const core::FrameReport r = sim.runFrame(k);
    pairTests += r.pairTests;
    benchmark::DoNotOptimize(r.contacts.data());
    k = (k + 1) % frames;
  }
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["pair_tests/frame"] =
      static_cast<double>(pairTests) / static_cast<double>(state.iterations());
  state.SetLabel(std::to_string(sim.threads()) + " threads");
}

void runFrames(benchmark::State& state, const char* sceneName) {
  core::RunOptions options;
  options.threads = static_cast<int>(state.range(0));
  runFramesOf(state, core::builtinExperimentScene(sceneName), options);
}

// range(0): triangles per block; range(1): 0 the reference mode, 1 skip-apart; one thread.
void runLevel(benchmark::State& state, const char* sceneName) {
  core::RunOptions options;
  options.threads = 1;
  options.pairMode = state.range(1) == 0 ? core::PairMode::Reference : core::PairMode::SkipApart;
  runFramesOf(state, core::builtinExperimentScene(sceneName, static_cast<int>(state.range(0))),
              options);
}

BENCHMARK_CAPTURE(runFrames, random_cones, "random-cones")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Arg(0)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runFrames, hand_grasp, "hand-grasp")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Arg(0)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(runLevel, hand_grasp, "hand-grasp")
    ->ArgNames({"per_block", "skip_apart"})
    ->ArgsProduct({{2304}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runLevel, comb_translate_aligned, "comb-translate-aligned")
    ->ArgNames({"per_block", "skip_apart"})
    ->ArgsProduct({{4096}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runLevel, hierarchy_9, "hierarchy-9")
    ->ArgNames({"per_block", "skip_apart"})
    ->ArgsProduct({{2880}, {0}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
