#include "recode/kit/buffer_diff.hpp"

#include <stdexcept>

namespace recode::kit {

std::string_view toString(Buffer b) {
  return b == Buffer::Depth ? "depth" : "stencil";
}

std::optional<PixelDifference> BufferComparison::first() const {
  if (differences.empty())
    return std::nullopt;
  return differences.front();
}

BufferComparison compareBuffers(const raster::GoldenVector& golden,
                                std::span<const std::uint32_t> depth,
                                std::span<const std::uint8_t> stencil, std::size_t limit) {
  const int w = golden.stream.width, h = golden.stream.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (depth.size() != n || stencil.size() != n || golden.depth.size() != n ||
      golden.stencil.size() != n) {
    throw std::invalid_argument("compareBuffers: buffers are not " + std::to_string(w) + "x" +
                                std::to_string(h));
  }
  BufferComparison out;
  const auto note = [&](std::size_t i, Buffer b, std::uint32_t expected, std::uint32_t got) {
    if (out.differences.size() < limit) {
      out.differences.push_back({static_cast<int>(i % static_cast<std::size_t>(w)),
                                 static_cast<int>(i / static_cast<std::size_t>(w)), b, expected,
                                 got});
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (depth[i] != golden.depth[i]) {
      ++out.depthPixels;
      note(i, Buffer::Depth, golden.depth[i], depth[i]);
    }
    if (stencil[i] != golden.stencil[i]) {
      ++out.stencilPixels;
      note(i, Buffer::Stencil, golden.stencil[i], stencil[i]);
    }
  }
  return out;
}

}  // namespace recode::kit
