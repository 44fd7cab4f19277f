// The vertex-stage vectors as a golden file (vertex_stage_vectors.hpp; the format is
// docs/rasterization.md, section 9): JSON Lines, a header and then one vector per line.

#include <bit>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/kit/vertex_stage_vectors.hpp"

namespace recode::kit {

namespace {

using nlohmann::ordered_json;

constexpr const char* kFormat = "recode-vertex-stage-1";

std::string floatBits(float value) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08" PRIx32, std::bit_cast<std::uint32_t>(value));
  return buf;
}

ordered_json hexArray(const double* values, std::size_t count) {
  ordered_json out = ordered_json::array();
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(hexDouble(values[i]));
  return out;
}

ordered_json vectorLine(const VertexStageVector& v) {
  const raster::Pose& pose = v.transform.pose;
  const raster::WindowMapping& m = v.transform.window;
  ordered_json local = ordered_json::array();
  for (const std::array<double, 3>& p : v.local)
    local.push_back(hexArray(p.data(), p.size()));
  ordered_json expected = ordered_json::array();
  ordered_json bits = ordered_json::array();
  for (const raster::WindowVertex& w : v.expected) {
    // A float converted to double prints as the shortest decimal that reads back as it, as
    // golden files write depths (section 8); -0 prints as -0.0.
    expected.push_back(
        {static_cast<double>(w.x), static_cast<double>(w.y), static_cast<double>(w.z)});
    bits.push_back({floatBits(w.x), floatBits(w.y), floatBits(w.z)});
  }
  ordered_json line;
  line["name"] = v.name;
  line["pose"] = {{"linear", hexArray(pose.linear.data(), pose.linear.size())},
                  {"translation", hexArray(pose.translation.data(), pose.translation.size())}};
  line["window"] = {{"axes", m.axes},
                    {"umin", hexDouble(m.umin)},
                    {"urange", hexDouble(m.urange)},
                    {"width", hexDouble(m.width)},
                    {"vmin", hexDouble(m.vmin)},
                    {"vrange", hexDouble(m.vrange)},
                    {"height", hexDouble(m.height)},
                    {"depth_max", hexDouble(m.depthMax)},
                    {"depth_range", hexDouble(m.depthRange)}};
  line["local"] = local;
  line["expected"] = expected;
  line["expected_bits"] = bits;
  return line;
}

}  // namespace

std::string hexDouble(double value) {
  if (!std::isfinite(value))
    throw std::invalid_argument("hexDouble: not a finite number");
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const std::string sign = (bits >> 63) != 0 ? "-" : "";
  const auto exponent = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  if (exponent == 0 && mantissa == 0)
    return sign + "0x0.0p+0";
  char buf[40];
  // Normal: 0x1.<13 hex digits>p<exponent>; subnormal: 0x0.<13 hex digits>p-1022.
  std::snprintf(buf, sizeof buf, "0x%c.%013" PRIx64 "p%+d", exponent == 0 ? '0' : '1', mantissa,
                exponent == 0 ? -1022 : exponent - 1023);
  return sign + buf;
}

std::string vertexStageGoldenText(const std::vector<VertexStageVector>& vectors) {
  std::size_t vertices = 0;
  for (const VertexStageVector& v : vectors)
    vertices += v.local.size();
  ordered_json header;
  header["format"] = kFormat;
  header["description"] =
      "The vertex stage of docs/rasterization.md section 2.1: each following line is one vector, "
      "a block's pose and view mapping with its local vertices and the window vertices the "
      "contract makes of them. Doubles are hexadecimal strings (Python: float.fromhex); "
      "expected x, y, z are floats, as decimals and as 32-bit patterns.";
  header["vectors"] = vectors.size();
  header["vertices"] = vertices;
  std::string out = header.dump() + "\n";
  for (const VertexStageVector& v : vectors)
    out += vectorLine(v).dump() + "\n";
  return out;
}

}  // namespace recode::kit
