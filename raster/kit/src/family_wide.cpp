// Wide frames: 16384 x 1, 16384 x 2 and 1 x 16384 (the largest frame side), with long slivers
// along the frame whose depth runs from near 0 to near 1 over 16384 pixels: traversal and
// coverage at the far end of the largest frame, and a plane evaluated in float drifts there.
// (In double, even 16384 steps from pixel (0, 0) stay far below a depth step: the anchor family
// catches those variants, not this one.) Kept small: one or two pixels across.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

Candidate wideFrames(Rng& rng, int index) {
  Candidate c;
  const bool tall = index % 3 == 2;
  const int across = index % 3 == 1 ? 2 : 1;
  c.width = tall ? across : 16384;
  c.height = tall ? 16384 : across;
  c.targets = {Variant::PlaneFromOrigin, Variant::IncrementalFromPixel00, Variant::FloatPlane,
               Variant::EdgeFloat};
  c.description = "A " + std::to_string(c.width) + " x " + std::to_string(c.height) +
                  " frame crossed by long slivers whose depth runs from near 0 to near 1, one "
                  "edge through the samples; stencil counts front and back fragments.";
  c.commands = countFacingsKeepDepth();
  const long long length = 256LL * 16384;
  cmd::Draw d;
  for (int s = 0; s < 3; ++s) {
    // Along the long axis u, across it v (in sub-pixels).
    const long long u0 = -rng.uniform(0, 256 * 64), u1 = length + rng.uniform(0, 256 * 64);
    const long long v0 = centre(rng.uniform(0, across - 1));
    const long long v1 = v0 + rng.uniform(-300, 300);
    const long long v2 = v0 + (rng.chance(50) ? 1 : -1) * rng.uniform(64, 512);
    const long long um = rng.uniform(u0, u1);
    const float z0 = rng.depth() / 16.0f, z1 = 1.0f - rng.depth() / 16.0f;
    const auto vertex = [tall](long long u, long long v, float z) {
      return tall ? fixedVertex(v, u, z) : fixedVertex(u, v, z);
    };
    const auto base = static_cast<std::uint32_t>(d.vertices.size());
    d.vertices.push_back(vertex(u0, v0, z0));
    d.vertices.push_back(vertex(u1, v1, z1));
    d.vertices.push_back(vertex(um, v2, rng.depth()));
    d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
  }
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
