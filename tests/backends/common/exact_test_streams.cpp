#include "exact_test_streams.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace recode::verify::testing {

using raster::CompareFunc;
using raster::Face;
using raster::StencilOp;
using raster::WindowVertex;

#if RECODE_HAVE_GL_EXACT
std::vector<backends::GlPlatform> exactGlPlatformsHere(std::vector<std::string>& unavailable) {
  std::vector<backends::GlPlatform> list;
  if (backends::glPlatformBuilt(backends::GlPlatform::OsMesa))
    list.push_back(backends::GlPlatform::OsMesa);
  if (backends::glPlatformBuilt(backends::GlPlatform::Egl)) {
    try {
      backends::GlExactDevice probe(1, 1, backends::GlPlatform::Egl);
      list.push_back(backends::GlPlatform::Egl);
    } catch (const std::runtime_error& e) {
      unavailable.push_back(std::string("EGL exact device unavailable here: ") + e.what());
    }
  }
  return list;
}
#endif

std::vector<std::filesystem::path> goldenFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(RECODE_DATA_DIR "/golden"))
    if (entry.path().extension() == ".json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string describe(const ExactParityReport& r) {
  if (r.examples.empty())
    return "no difference";
  const auto& e = r.examples.front();
  return "command " + std::to_string(e.command) + " pixel (" + std::to_string(e.x) + ", " +
         std::to_string(e.y) + "): depth " + std::to_string(e.referenceDepth) + " vs " +
         std::to_string(e.candidateDepth) + ", stencil " + std::to_string(e.referenceStencil) +
         " vs " + std::to_string(e.candidateStencil);
}

raster::CommandStream randomStream(std::mt19937& rng, int width, int height) {
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const auto unit = [&] { return std::uniform_real_distribution<float>(0.0f, 1.0f)(rng); };
  raster::CommandStream stream;
  stream.width = width;
  stream.height = height;
  for (int k = 0; k < 30; ++k) {
    switch (pick(10)) {
      case 0:
        stream.commands.emplace_back(raster::cmd::Scissor{
            {pick(width) - 4, pick(height) - 4, pick(width) + 8, pick(height) + 8}});
        break;
      case 1:
        stream.commands.emplace_back(raster::cmd::ClearDepth{unit()});
        break;
      case 2:
        stream.commands.emplace_back(raster::cmd::ClearStencil{std::uint8_t(pick(256))});
        break;
      case 3:
        stream.commands.emplace_back(raster::cmd::DepthFunc{CompareFunc(pick(8))});
        stream.commands.emplace_back(raster::cmd::DepthWriteMask{pick(4) != 0});
        break;
      case 4:
        stream.commands.emplace_back(
            raster::cmd::StencilFunc{CompareFunc(pick(8)), std::uint8_t(pick(256)),
                                     std::uint8_t(pick(2) ? 0xFF : pick(256))});
        break;
      case 5:
        stream.commands.emplace_back(raster::cmd::StencilOpsCmd{
            Face(pick(3)), {StencilOp(pick(8)), StencilOp(pick(8)), StencilOp(pick(8))}});
        break;
      case 6:
        stream.commands.emplace_back(
            raster::cmd::StencilWriteMask{std::uint8_t(pick(2) ? 0xFF : pick(256))});
        stream.commands.emplace_back(raster::cmd::Cull{raster::CullMode(pick(3))});
        break;
      default: {
        raster::cmd::Draw draw;
        const int triangles = 1 + pick(6);
        for (int t = 0; t < triangles; ++t) {
          const bool far = pick(5) == 0;     // a vertex in the guard band
          const bool sliver = pick(3) == 0;  // a long thin triangle with a steep plane
          // Positions on the 1/256 grid, or on pixel centres and edges (where the fill rule
          // decides), or on whole pixels.
          const int grid = std::vector<int>{1, 128, 256}[pick(3)];
          const auto coordinate = [&](int extent) {
            const int span = far ? 65536 * 256 : (extent + 8) * 256;
            const int offset = far ? 32768 * 256 : 4 * 256;
            return float((pick(span) - offset) / grid * grid) / 256.0f;
          };
          WindowVertex a{coordinate(width), coordinate(height), unit()};
          WindowVertex b{coordinate(width), coordinate(height), unit()};
          WindowVertex c = sliver ? WindowVertex{b.x + float(pick(5) - 2) / 256.0f,
                                                 b.y + float(pick(5) - 2) / 256.0f, unit()}
                                  : WindowVertex{coordinate(width), coordinate(height), unit()};
          for (const WindowVertex& v : {a, b, c}) {
            draw.indices.push_back(static_cast<std::uint32_t>(draw.vertices.size()));
            draw.vertices.push_back(v);
          }
        }
        stream.commands.emplace_back(std::move(draw));
      }
    }
  }
  return stream;
}

}  // namespace recode::verify::testing
