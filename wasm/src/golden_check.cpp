#include "golden_check.hpp"

#include <nlohmann/json.hpp>

#include "recode/kit/buffer_diff.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"

namespace recode::wasm {

std::string checkGolden(const std::string& path) {
  const raster::GoldenVector g = raster::readGolden(path);
  raster::CpuDevice device(g.stream.width, g.stream.height);
  raster::replay(g.stream.commands, device);
  const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
  const kit::BufferComparison cmp =
      kit::compareBuffers(g, device.readDepth(all), device.readStencil(all), 1);
  nlohmann::ordered_json j;
  j["depth_pixels"] = cmp.depthPixels;
  j["stencil_pixels"] = cmp.stencilPixels;
  j["first_difference"] = nullptr;
  if (const auto first = cmp.first())
    j["first_difference"] = {{"x", first->x},
                             {"y", first->y},
                             {"buffer", kit::toString(first->buffer)},
                             {"expected", first->expected},
                             {"got", first->got}};
  return j.dump();
}

}  // namespace recode::wasm
