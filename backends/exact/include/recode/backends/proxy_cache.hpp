#pragma once
// The proxies of the blocks an exact GPU device drew last, kept by the block's content key
// (raster::TriangleSource::contentKey) and scissor. A pair test draws each of its two blocks
// under one scissor in several passes (docs/algorithm.md, "The passes": A twice, B three
// times, then both twice more over the contact rectangle), and only the cull mode differs
// between them; setting up the triangles (snapping, the depth plane's correctly rounded
// divisions, the bands) once per block and scissor takes most of that host work out of a frame.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "recode/backends/exact_proxy.hpp"
#include "recode/raster/state.hpp"
#include "recode/raster/triangle_source.hpp"

namespace recode::backends {

class ProxyCache {
 public:
  // The proxies of one draw, and a number that names exactly this list while the cache holds
  // it (a device may keep what it made of the list, e.g. an upload, under that number).
  struct Proxies {
    const std::vector<ProxyTriangle>* list = nullptr;
    std::uint64_t id = 0;
  };

  // The proxies of source drawn in `state`: the same records in the same order as
  // buildProxyTriangles(trianglesToDraw(source, state.scissor), state). A source without a
  // content key is set up anew each time. The list stays valid until the next call.
  // Throws what buildProxyTriangles throws (an invalid draw), caching nothing then.
  [[nodiscard]] Proxies proxies(const raster::TriangleSource& source,
                                const raster::RenderState& state);

  // Blocks (with their scissors) kept: a pair test's two, and the last pair's while the next
  // one starts.
  static constexpr std::size_t kKeptBlocks = 4;

 private:
  // One block under one scissor: its proxies for each cull mode, made when first asked (those
  // of a culling mode are the unculled ones of the kept facing, since a triangle's proxies do
  // not depend on the cull mode).
  struct Entry {
    std::uint64_t key = 0;  // TriangleSource::contentKey, never 0 for a block held
    raster::PixelRect scissor;
    std::array<std::vector<ProxyTriangle>, 3> byCull;  // indexed by raster::CullMode
    std::array<std::uint64_t, 3> ids{};  // each list's id once made, 0 before (ids start at 1)
  };

  Entry& entryFor(const raster::TriangleSource& source, const raster::RenderState& state);

  std::array<Entry, kKeptBlocks> entries_{};  // a key of 0: none held; the next to replace at next_
  std::size_t next_ = 0;
  std::vector<ProxyTriangle> uncached_;  // the last draw of a source without a key
  std::uint64_t lastId_ = 0;
};

}  // namespace recode::backends
