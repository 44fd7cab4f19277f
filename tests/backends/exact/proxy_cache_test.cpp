// ProxyCache (backends/exact/.../proxy_cache.hpp) against its definition: whatever blocks,
// scissors and cull modes are asked in whatever order, each answer is the records
// buildProxyTriangles makes of trianglesToDraw(source, scissor) in that state, and an id names
// one list only, so an upload kept under it is never drawn for another.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "recode/backends/exact_proxy.hpp"
#include "recode/backends/proxy_cache.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/triangle_source.hpp"

using namespace recode;
using backends::ProxyCache;
using backends::ProxyTriangle;
using raster::CullMode;
using raster::PixelRect;

namespace {

// A block of random triangles in a 64 x 64 window, named by a content key or not.
class RandomBlock final : public raster::TriangleSource {
 public:
  RandomBlock(std::uint32_t seed, bool keyed) : key_(keyed ? raster::newTriangleSourceKey() : 0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xy(-4.0f, 68.0f);
    std::uniform_real_distribution<float> z(0.0f, 1.0f);
    for (std::uint32_t i = 0; i < 3 * 40; ++i) {
      vertices_.push_back({xy(rng), xy(rng), z(rng)});
      indices_.push_back(i);
    }
  }
  [[nodiscard]] raster::TriangleDraw allTriangles() const override {
    ++drawsMade;
    return {vertices_, indices_};
  }
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }
  void spoil() { vertices_[0].x = std::nanf(""); }  // a draw drawTriangles refuses

  mutable int drawsMade = 0;

 private:
  std::uint64_t key_;
  std::vector<raster::WindowVertex> vertices_;
  std::vector<std::uint32_t> indices_;
};

raster::RenderState stateWith(const PixelRect& scissor, CullMode cull) {
  raster::RenderState state = raster::initialRenderState(64, 64);
  state.scissor = scissor;
  state.cull = cull;
  return state;
}

bool sameRecords(const std::vector<ProxyTriangle>& a, const std::vector<ProxyTriangle>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(ProxyTriangle)) == 0);
}

}  // namespace

TEST_CASE("the proxy cache answers what buildProxyTriangles makes, for any order of draws",
          "[proxy-cache]") {
  std::vector<RandomBlock> blocks;
  for (std::uint32_t b = 0; b < 7; ++b)
    blocks.emplace_back(b + 1, b != 3);  // block 3 has no content key
  const std::vector<PixelRect> scissors = {{0, 0, 64, 64}, {10, 12, 40, 30}, {10, 12, 40, 31}};
  const CullMode culls[] = {CullMode::None, CullMode::Front, CullMode::Back};
  ProxyCache cache;
  std::mt19937 rng(9);
  // Ids handed out for each (block, scissor, cull) while the list is held: one list, one id.
  std::map<std::uint64_t, std::tuple<std::size_t, std::size_t, int>> named;
  int mismatches = 0;
  for (int call = 0; call < 600; ++call) {
    // Mostly the last two blocks again (the passes of a pair), sometimes any block.
    const std::size_t b = rng() % 4 == 0 ? rng() % blocks.size() : 5 + rng() % 2;
    const std::size_t s = rng() % scissors.size();
    const int c = static_cast<int>(rng() % 3);
    const raster::RenderState state = stateWith(scissors[s], culls[c]);
    const ProxyCache::Proxies got = cache.proxies(blocks[b], state);
    const raster::TriangleDraw draw = raster::trianglesToDraw(blocks[b], state.scissor);
    const std::vector<ProxyTriangle> want =
        backends::buildProxyTriangles(draw.vertices, draw.indices, state);
    if (!sameRecords(*got.list, want))
      ++mismatches;
    const auto [it, added] = named.try_emplace(got.id, b, s, c);
    if (!added && it->second != std::tuple{b, s, c})
      FAIL("id " << got.id << " named two different lists");
  }
  CHECK(mismatches == 0);
}

TEST_CASE("the proxy cache sets a block up once for every pass under one scissor",
          "[proxy-cache]") {
  RandomBlock a(1, true), b(2, true);
  ProxyCache cache;
  const PixelRect mor{8, 8, 48, 40};
  // A pair test's stencil passes: A, B, A, B culling back faces, B culling front faces.
  const ProxyCache::Proxies first = cache.proxies(a, stateWith(mor, CullMode::None));
  (void)cache.proxies(b, stateWith(mor, CullMode::None));
  const ProxyCache::Proxies again = cache.proxies(a, stateWith(mor, CullMode::None));
  (void)cache.proxies(b, stateWith(mor, CullMode::Back));
  (void)cache.proxies(b, stateWith(mor, CullMode::Front));
  CHECK(a.drawsMade == 1);
  CHECK(b.drawsMade == 1);
  CHECK(again.id == first.id);
  // Another scissor is another set-up.
  (void)cache.proxies(a, stateWith({8, 8, 20, 20}, CullMode::None));
  CHECK(a.drawsMade == 2);
  // A block pushed out by kKeptBlocks others is set up again, under a new id.
  std::vector<RandomBlock> others;
  for (std::uint32_t k = 0; k < ProxyCache::kKeptBlocks; ++k)
    others.emplace_back(10 + k, true);
  for (const RandomBlock& other : others)
    (void)cache.proxies(other, stateWith(mor, CullMode::None));
  const ProxyCache::Proxies remade = cache.proxies(a, stateWith(mor, CullMode::None));
  CHECK(a.drawsMade == 3);
  CHECK(remade.id != first.id);
}

TEST_CASE("the proxy cache keeps nothing of a draw it refuses", "[proxy-cache]") {
  RandomBlock block(4, true);
  block.spoil();
  ProxyCache cache;
  const raster::RenderState state = stateWith({0, 0, 64, 64}, CullMode::None);
  CHECK_THROWS_AS(cache.proxies(block, state), std::invalid_argument);
  CHECK_THROWS_AS(cache.proxies(block, state), std::invalid_argument);
  CHECK(block.drawsMade == 2);
}
