// Fans: triangles around a shared vertex on a pixel centre whose spokes run through sample
// points (the four axes always among them), each triangle of either winding: every sample of
// the fan must be drawn exactly once, by the triangle whose edges own it.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

// Integer directions in counter-clockwise order; consecutive ones of any subset that keeps the
// four axes are less than 180 degrees apart, so the fan closes without overlap.
constexpr long long kDirections[16][2] = {{1, 0},  {2, 1},  {1, 1},  {1, 2},   {0, 1},   {-1, 2},
                                          {-1, 1}, {-2, 1}, {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2},
                                          {0, -1}, {1, -2}, {1, -1}, {2, -1}};

}  // namespace

Candidate fans(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::TopLeftFill, Variant::SwappedFacing};
  Candidate c;
  c.width = static_cast<int>(rng.uniform(13, 21));
  c.height = static_cast<int>(rng.uniform(13, 21));
  c.targets = {kTargets[index % 2]};
  c.description =
      "A fan around a vertex on the centre of a pixel, spokes through sample points, each "
      "triangle of either winding and submitted from any corner: every sample of the fan once "
      "(stencil 1 for a front fragment, 255 for a back one).";
  c.commands = countFacingsKeepDepth();
  const long long cx = centre(rng.uniform(c.width / 4, 3 * c.width / 4));
  const long long cy = centre(rng.uniform(c.height / 4, 3 * c.height / 4));
  cmd::Draw d;
  d.vertices.push_back(fixedVertex(cx, cy, rng.depth()));
  for (int k = 0; k < 16; ++k) {
    if (k % 4 != 0 && rng.chance(40))
      continue;
    const long long s = 256 * rng.uniform(2, 9);
    d.vertices.push_back(
        fixedVertex(cx + kDirections[k][0] * s, cy + kDirections[k][1] * s, rng.depth()));
  }
  const auto rim = static_cast<std::uint32_t>(d.vertices.size() - 1);
  for (std::uint32_t k = 0; k < rim; ++k) {
    std::uint32_t t[3] = {0, 1 + k, 1 + (k + 1) % rim};
    if (rng.chance(50))
      std::swap(t[1], t[2]);
    const auto r = static_cast<std::uint32_t>(rng.uniform(0, 2));
    for (std::uint32_t j = 0; j < 3; ++j)
      d.indices.push_back(t[(r + j) % 3]);
  }
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
