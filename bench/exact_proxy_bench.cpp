// The exact GPU devices' host half: setting a draw's triangles up as proxy records
// (backends::buildProxyTrianglesInto, as ProxyCache does it). At large levels this set-up is
// much of a Vulkan frame's host work (docs/benchmarks.md, "Where a GPU device's frame goes").

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "recode/backends/exact_proxy.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/state.hpp"

namespace {

using namespace recode;

// `triangles` small triangles (a fine mesh's, a few pixels each) over a 512 x 512 window.
struct Draw {
  std::vector<raster::WindowVertex> vertices;
  std::vector<std::uint32_t> indices;
};

Draw fineMesh(std::size_t triangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> xy(0.0f, 512.0f), d(-3.0f, 3.0f), z(0.0f, 1.0f);
  Draw draw;
  for (std::size_t t = 0; t < triangles; ++t) {
    const float x = xy(rng), y = xy(rng);
    for (std::uint32_t k = 0; k < 3; ++k) {
      draw.indices.push_back(static_cast<std::uint32_t>(draw.vertices.size()));
      draw.vertices.push_back({x + d(rng), y + d(rng), z(rng)});
    }
  }
  return draw;
}

void BM_ProxySetup(benchmark::State& state) {
  const Draw draw = fineMesh(static_cast<std::size_t>(state.range(0)));
  const raster::RenderState render = raster::initialRenderState(512, 512);
  std::vector<backends::ProxyTriangle> proxies;
  for (auto _ : state) {
    backends::buildProxyTrianglesInto(draw.vertices, draw.indices, render, proxies);
    benchmark::DoNotOptimize(proxies.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_ProxySetup)->Name("proxySetup")->Arg(512)->Arg(4096)->Arg(32768);

}  // namespace

BENCHMARK_MAIN();
