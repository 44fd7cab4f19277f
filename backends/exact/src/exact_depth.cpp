#include "recode/backends/exact_depth.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/state.hpp"

namespace recode::backends {

std::vector<std::uint32_t> depthFromStoredFloats(std::span<const std::uint8_t> bytes,
                                                 std::string_view device) {
  std::vector<std::uint32_t> out(bytes.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i) {
    float stored = 0.0f;
    std::memcpy(&stored, bytes.data() + 4 * i, 4);
    const double q = static_cast<double>(stored) * 16777216.0;
    if (!(q >= 0.0 && q <= static_cast<double>(raster::kDepthMax)) || q != std::floor(q)) {
      throw std::runtime_error(std::string(device) + ": the depth buffer holds " +
                               std::to_string(stored) + ", not a multiple of 2^-24 below 1");
    }
    out[i] = static_cast<std::uint32_t>(q);
  }
  return out;
}

}  // namespace recode::backends
