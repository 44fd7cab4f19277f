// The oracles' speed on the generated pair suite (verify::generatePairSuite): Embree rays per
// second, CGAL time per pair, and RECODE's pair algorithm on the GL device (OSMesa llvmpipe)
// against the CPU reference on the same pairs. Each benchmark is compiled only when its oracle
// is in the build.
//
//   build/bench/recode_verify_bench --benchmark_min_time=1

#include <benchmark/benchmark.h>

#include <map>
#include <vector>

#include "recode/backends/gl_device.hpp"
#include "recode/backends/gl_exact_device.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "recode/verify/embree_oracle.hpp"
#include "recode/verify/pair_suite.hpp"
#ifdef RECODE_HAVE_VULKAN
#include "recode/backends/vulkan_device.hpp"
#endif

namespace {

using namespace recode;

// The suite at one width with RECODE's results (minimal MOR), made once per width.
struct SuiteRun {
  std::vector<verify::SuitePair> pairs;
  std::vector<core::PairResult> results;
};

const SuiteRun& suiteAt(int width) {
  static std::map<int, SuiteRun> cache;
  auto it = cache.find(width);
  if (it != cache.end())
    return it->second;
  SuiteRun run;
  verify::PairSuiteOptions options;
  options.width = width;
  run.pairs = verify::generatePairSuite(options);
  for (const verify::SuitePair& p : run.pairs) {
    raster::CpuDevice device(p.frame.width, p.frame.height);
    core::PairRequest request;
    request.frame = p.frame;
    run.results.push_back(core::collidePair(device, p.a, p.b, request));
  }
  return cache.emplace(width, std::move(run)).first->second;
}

[[maybe_unused]] core::PairRequest requestFor(const verify::SuitePair& p) {
  core::PairRequest request;
  request.frame = p.frame;
  return request;
}

#ifdef RECODE_HAVE_EMBREE
// One EmbreeOracle::check per suite pair (scene builds, rays, classification).
void embreeCheckSuite(benchmark::State& state) {
  const SuiteRun& run = suiteAt(static_cast<int>(state.range(0)));
  verify::EmbreeOracle oracle;
  long long rays = 0, pixels = 0, unexplained = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < run.pairs.size(); ++i) {
      const verify::EmbreeReport r =
          oracle.check(run.pairs[i].frame, run.pairs[i].a, run.pairs[i].b, run.results[i]);
      rays += r.rays;
      pixels += r.counts.pixels;
      unexplained += r.counts.unexplained;
    }
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
  state.counters["pixels_per_s"] =
      benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate);
  state.counters["unexplained"] = static_cast<double>(unexplained);
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(run.pairs.size()));
}
BENCHMARK(embreeCheckSuite)->Arg(64)->Arg(256)->ArgName("width")->Unit(benchmark::kMillisecond);
#endif

#ifdef RECODE_HAVE_CGAL
// exactIntersection + judgePair per suite pair; items/s is pairs per second.
void cgalSuite(benchmark::State& state) {
  const SuiteRun& run = suiteAt(64);
  long long disagree = 0;
  for (auto _ : state)
    for (std::size_t i = 0; i < run.pairs.size(); ++i) {
      const verify::SuitePair& p = run.pairs[i];
      const verify::ExactIntersection exact = verify::exactIntersection(p.a, p.b);
      const verify::CgalJudgement j = verify::judgePair(exact, p.frame, p.a, p.b, run.results[i]);
      disagree += j.verdict == verify::VerdictCheck::Disagree ? 1 : 0;
    }
  state.counters["disagree"] = static_cast<double>(disagree);
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(run.pairs.size()));
}
BENCHMARK(cgalSuite)->Unit(benchmark::kMillisecond);
#endif

// RECODE on every suite pair on a device of each kind. Suite frames share the width but not the
// height, so pairs are grouped by height and each group runs on one device, created (and, for
// GL, warmed up by one untimed pair: llvmpipe compiles its shaders on the first draws) with the
// timer paused. The figure is the steady state of a device in use, not a context's start-up
// (about 5 ms for OSMesa). The pair algorithm sets all the state it relies on, so a device can
// be reused; the collision count is the same as on fresh devices.
template <class Device, auto... DeviceArguments>
void pairsOnDevice(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const SuiteRun& run = suiteAt(width);
  std::map<int, std::vector<const verify::SuitePair*>> byHeight;
  for (const verify::SuitePair& p : run.pairs)
    byHeight[p.frame.height].push_back(&p);
  long long collisions = 0;
  for (auto _ : state)
    for (const auto& [height, pairs] : byHeight) {
      state.PauseTiming();
      auto device = std::make_unique<Device>(width, height, DeviceArguments...);
      benchmark::DoNotOptimize(
          core::collidePair(*device, pairs[0]->a, pairs[0]->b, requestFor(*pairs[0])));
      state.ResumeTiming();
      for (const verify::SuitePair* p : pairs)
        collisions += core::collidePair(*device, p->a, p->b, requestFor(*p)).collide ? 1 : 0;
      state.PauseTiming();
      device.reset();
      state.ResumeTiming();
    }
  state.counters["collisions"] =
      static_cast<double>(collisions) / static_cast<double>(state.iterations());
  state.counters["devices"] = static_cast<double>(byHeight.size());
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(run.pairs.size()));
}
BENCHMARK(pairsOnDevice<raster::CpuDevice>)
    ->Arg(64)
    ->Arg(512)
    ->ArgName("width")
    ->Unit(benchmark::kMillisecond);
#ifdef RECODE_HAVE_GL_DEVICE
BENCHMARK(pairsOnDevice<backends::GlDevice>)
    ->Arg(64)
    ->Arg(512)
    ->ArgName("width")
    ->Unit(benchmark::kMillisecond);
#endif
#ifdef RECODE_HAVE_GL_EXACT
BENCHMARK(pairsOnDevice<backends::GlExactDevice, backends::GlPlatform::OsMesa>)
    ->Arg(64)
    ->Arg(512)
    ->ArgName("width")
    ->Unit(benchmark::kMillisecond);
#endif
#ifdef RECODE_HAVE_EGL
BENCHMARK(pairsOnDevice<backends::GlExactDevice, backends::GlPlatform::Egl>)
    ->Arg(64)
    ->Arg(512)
    ->ArgName("width")
    ->Unit(benchmark::kMillisecond);
#endif

#ifdef RECODE_HAVE_VULKAN
BENCHMARK(pairsOnDevice<backends::VulkanDevice>)
    ->Arg(64)
    ->Arg(512)
    ->ArgName("width")
    ->Unit(benchmark::kMillisecond);
#endif

#ifdef RECODE_HAVE_GL_EXACT
// Making an exact GL device once the process's shared context and program exist (the first
// device of a platform also pays for the context and the shader compilation; see
// docs/backends.md for that figure).
void exactDeviceCreation(benchmark::State& state) {
  const auto platform = static_cast<backends::GlPlatform>(state.range(0));
  const int size = static_cast<int>(state.range(1));
  { backends::GlExactDevice warm(1, 1, platform); }
  for (auto _ : state) {
    backends::GlExactDevice device(size, size, platform);
    benchmark::DoNotOptimize(device.width());
  }
}
BENCHMARK(exactDeviceCreation)
    ->Args({static_cast<int>(backends::GlPlatform::OsMesa), 64})
    ->Args({static_cast<int>(backends::GlPlatform::OsMesa), 512})
    ->ArgNames({"platform", "size"})
    ->Unit(benchmark::kMicrosecond);
#endif

}  // namespace

BENCHMARK_MAIN();
