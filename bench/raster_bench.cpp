// Rasterizer throughput: depth+stencil fill rate for large triangles inside a scissor, and
// triangle setup rate for small triangles.
//
//   build/bench/recode_raster_bench --benchmark_min_time=1
//
// Items processed are pixels written (fill) or triangles submitted (setup), so Google
// Benchmark's items_per_second column reads as pixels/s or triangles/s.

#include <benchmark/benchmark.h>

#include <iterator>
#include <random>
#include <vector>

#include "recode/raster/block_fragments.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"

using namespace recode::raster;

namespace {

// The state of RECODE's RenderTestZ pass: a depth test, no depth write, a stencil test and
// an increment, so each fragment reads depth and reads and writes stencil.
void setPassState(CpuDevice& dev) {
  dev.setDepthFunc(CompareFunc::LEqual);
  dev.setDepthWriteMask(true);
  dev.setStencilFunc(CompareFunc::LEqual, 0, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
}

// Two triangles (a sloped quad) that cover a size x size scissor in a 1024x1024 framebuffer.
void BM_FillQuad(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  CpuDevice dev(1024, 1024);
  dev.setScissor({100, 100, 100 + size, 100 + size});
  setPassState(dev);
  const float far = 110.0f + static_cast<float>(size);
  const std::vector<WindowVertex> v = {
      {90.0f, 90.0f, 0.1f}, {far, 90.0f, 0.4f}, {far, far, 0.6f}, {90.0f, far, 0.3f}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
  for (auto _ : state) {
    dev.clearDepth(1.0);
    dev.drawTriangles(v, idx);
    benchmark::DoNotOptimize(dev.stencilBuffer().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(size) * size);
  state.counters["pixels_per_draw"] = static_cast<double>(size) * size;
}
BENCHMARK(BM_FillQuad)->Arg(64)->Arg(512)->Unit(benchmark::kMicrosecond);

// The states of RECODE's passes (core/pair/src/pair_passes.hpp), each drawn over a 512x512
// scissor as BM_FillQuad draws: the fill rate the pair test's passes see. Their compare
// functions and stencil ops are those the fragment stage has a kernel compiled for
// (detail::kCompiledFragmentFuncs, in the same order); the rest of each state is here.
struct PassState {
  const char* name;
  bool depthWrite;
  std::uint8_t ref;
  std::uint8_t valueMask;
  std::uint8_t writeMask;
};
const PassState kPassStates[] = {
    {"setZ", true, 1, 0xFF, 0xFF},     {"testZ", false, 1, 0x03, 0x03},
    {"loadAmin", true, 0, 0xFF, 0},    {"testAmin", false, 1, 0x03, 0x04},
    {"overlapNear", true, 0, 0xFF, 0},
};
static_assert(std::size(kPassStates) == detail::kCompiledFragmentKernels,
              "one pass state per compiled fragment kernel");

void BM_FillPass(benchmark::State& state) {
  const PassState& pass = kPassStates[state.range(0)];
  const detail::FragmentFuncs& funcs = detail::kCompiledFragmentFuncs[state.range(0)];
  state.SetLabel(pass.name);
  const int size = 512;
  CpuDevice dev(1024, 1024);
  dev.setScissor({100, 100, 100 + size, 100 + size});
  dev.setDepthFunc(funcs.depthFunc);
  dev.setDepthWriteMask(pass.depthWrite);
  dev.setStencilFunc(funcs.stencilFunc, pass.ref, pass.valueMask);
  dev.setStencilWriteMask(pass.writeMask);
  dev.setStencilOps(Face::Both, funcs.ops);
  const float far = 110.0f + static_cast<float>(size);
  const std::vector<WindowVertex> v = {
      {90.0f, 90.0f, 0.1f}, {far, 90.0f, 0.4f}, {far, far, 0.6f}, {90.0f, far, 0.3f}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
  for (auto _ : state) {
    dev.clearDepth(funcs.depthFunc == CompareFunc::GEqual ? 0.0 : 1.0);
    dev.drawTriangles(v, idx);
    benchmark::DoNotOptimize(dev.stencilBuffer().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(size) * size);
}
BENCHMARK(BM_FillPass)
    ->DenseRange(0, detail::kCompiledFragmentKernels - 1)
    ->Unit(benchmark::kMicrosecond);

// Many small random triangles (edge length about `range(0)` pixels) in a 512x512 frame.
void BM_SmallTriangles(benchmark::State& state) {
  const double edge = static_cast<double>(state.range(0));
  CpuDevice dev(512, 512);
  setPassState(dev);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> pos(8.0, 500.0), off(-edge, edge), z(0.0, 1.0);
  std::vector<WindowVertex> v;
  std::vector<std::uint32_t> idx;
  const int n = 20000;
  for (int t = 0; t < n; ++t) {
    const double x = pos(rng), y = pos(rng);
    for (int k = 0; k < 3; ++k) {
      v.push_back(
          {snapToSubpixel(x + off(rng)), snapToSubpixel(y + off(rng)), static_cast<float>(z(rng))});
      idx.push_back(static_cast<std::uint32_t>(idx.size()));
    }
  }
  for (auto _ : state) {
    dev.drawTriangles(v, idx);
    benchmark::DoNotOptimize(dev.stencilBuffer().data());
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["fragments_per_triangle"] = static_cast<double>(dev.counters().fragments) /
                                             static_cast<double>(dev.counters().trianglesSubmitted);
}
BENCHMARK(BM_SmallTriangles)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
