// Culling: triangles of both windings (and one that snaps to zero area) drawn under one cull
// mode, then more under another; front fragments count +1, back fragments -1, so a back end
// that takes the wrong facing, culls the wrong one or draws a zero-area triangle shows it.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

cmd::Draw randomTriangles(Rng& rng, int w, int h) {
  cmd::Draw d;
  const long long n = rng.uniform(2, 4);
  for (long long t = 0; t < n; ++t) {
    const auto base = static_cast<std::uint32_t>(d.vertices.size());
    for (int k = 0; k < 3; ++k) {
      d.vertices.push_back(fixedVertex(rng.uniform(-256, 256LL * w + 256),
                                       rng.uniform(-256, 256LL * h + 256), rng.depth()));
    }
    d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
  }
  // Three collinear vertices through sample points: zero area, never drawn.
  const auto base = static_cast<std::uint32_t>(d.vertices.size());
  const long long y = centre(rng.uniform(0, h - 1));
  d.vertices.push_back(fixedVertex(centre(0), y, 0.5f));
  d.vertices.push_back(fixedVertex(centre(w / 2), y, 0.5f));
  d.vertices.push_back(fixedVertex(centre(w - 1), y, 0.5f));
  d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
  return d;
}

}  // namespace

Candidate culling(Rng& rng, int index) {
  static const CullMode kModes[3] = {CullMode::None, CullMode::Front, CullMode::Back};
  const CullMode first = kModes[index % 3], second = kModes[(index / 3 + index + 1) % 3];
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {Variant::SwappedFacing};
  c.description = "Triangles of both windings and a zero-area one, drawn with cull " +
                  std::string(toString(first)) + ", then more with cull " +
                  std::string(toString(second)) +
                  "; stencil counts front (+1) and back (-1) fragments.";
  c.commands = countFacingsKeepDepth();
  c.commands.push_back(cmd::Cull{first});
  c.commands.push_back(randomTriangles(rng, c.width, c.height));
  c.commands.push_back(cmd::Cull{second});
  c.commands.push_back(randomTriangles(rng, c.width, c.height));
  return c;
}

}  // namespace recode::kit::detail
