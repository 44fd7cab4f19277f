#include "recode/backends/proxy_cache.hpp"

#include <algorithm>
#include <iterator>

namespace recode::backends {

ProxyCache::Proxies ProxyCache::proxies(const raster::TriangleSource& source,
                                        const raster::RenderState& state) {
  if (source.contentKey() == 0) {
    const raster::TriangleDraw draw = raster::trianglesToDraw(source, state.scissor);
    buildProxyTrianglesInto(draw.vertices, draw.indices, state, uncached_);
    return {&uncached_, ++lastId_};
  }
  Entry& entry = entryFor(source, state);
  const auto cull = static_cast<std::size_t>(state.cull);
  if (entry.ids[cull] == 0) {
    const std::vector<ProxyTriangle>& all =
        entry.byCull[static_cast<std::size_t>(raster::CullMode::None)];
    std::vector<ProxyTriangle>& kept = entry.byCull[cull];
    kept.clear();
    kept.reserve(all.size());
    std::copy_if(all.begin(), all.end(), std::back_inserter(kept),
                 [&](const ProxyTriangle& p) { return !state.culls(p.frontFacing != 0); });
    entry.ids[cull] = ++lastId_;
  }
  return {&entry.byCull[cull], entry.ids[cull]};
}

ProxyCache::Entry& ProxyCache::entryFor(const raster::TriangleSource& source,
                                        const raster::RenderState& state) {
  const std::uint64_t key = source.contentKey();
  for (Entry& entry : entries_)
    if (entry.key == key && entry.scissor == state.scissor)
      return entry;
  // Every proxy of the draw whatever its facing: the culling modes' lists are taken from it.
  raster::RenderState unculled = state;
  unculled.cull = raster::CullMode::None;
  // Made in the memory of the entry it replaces (a refused draw leaves that entry as it was).
  const raster::TriangleDraw draw = raster::trianglesToDraw(source, state.scissor);
  Entry& entry = entries_[next_];
  const auto none = static_cast<std::size_t>(raster::CullMode::None);
  buildProxyTrianglesInto(draw.vertices, draw.indices, unculled, entry.byCull[none]);
  next_ = (next_ + 1) % kKeptBlocks;
  entry.key = key;
  entry.scissor = state.scissor;
  entry.ids = {};
  entry.ids[none] = ++lastId_;
  return entry;
}

}  // namespace recode::backends
