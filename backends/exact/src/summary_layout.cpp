// The exact GPU devices' summary inputs, parameters and words.
#include "recode/backends/summary_layout.hpp"

#include <array>
#include <cstring>

namespace recode::backends {

SummaryInputs::SummaryInputs(const raster::PixelRect& rect, bool withDepth) {
  const auto pixels = static_cast<std::size_t>(rect.area());
  stencilBytes = (pixels + 3) / 4 * 4;
  farBytes = withDepth ? 4 * pixels : 0;
  tableBytes = raster::StencilClasses{}.classOf.size();
}

SummaryParameters summaryParameters(const raster::PixelRect& rect,
                                    const raster::StencilClasses& classes, bool withDepth,
                                    bool rowsFromBottom, std::size_t inputsOffset,
                                    std::size_t nearOffset, std::size_t resultOffset) {
  const SummaryInputs inputs(rect, withDepth);
  const auto word = [](std::size_t byteOffset) {
    return static_cast<std::uint32_t>(byteOffset / 4);
  };
  SummaryParameters p;
  p.stencilByte = static_cast<std::uint32_t>(inputsOffset);
  p.farWord = word(inputsOffset + inputs.farOffset());
  p.tableWord = word(inputsOffset + inputs.tableOffset());
  p.nearWord = withDepth ? word(nearOffset) : 0;
  p.resultWord = word(resultOffset);
  p.x0 = static_cast<std::uint32_t>(rect.x0);
  p.y0 = static_cast<std::uint32_t>(rect.y0);
  p.y1 = static_cast<std::uint32_t>(rect.y1);
  p.width = static_cast<std::uint32_t>(rect.width());
  p.height = static_cast<std::uint32_t>(rect.height());
  p.marked = classes.marked;
  p.withDepth = withDepth ? 1 : 0;
  p.rowsFromBottom = rowsFromBottom ? 1 : 0;
  return p;
}

raster::PixelSummary summaryFromBytes(const std::uint8_t* bytes, const raster::PixelRect& rect,
                                      bool withDepth, const char* device) {
  std::array<std::uint32_t, raster::kPixelSummaryWords> words{};
  std::memcpy(words.data(), bytes, raster::kPixelSummaryBytes);
  return raster::unpackPixelSummary(words, rect, withDepth, device);
}

}  // namespace recode::backends
