// Limits: triangles with vertices on the +-2^23 fixed-point box (+-32768 pixels), whose edges
// run through sample points of the framebuffer, with z exactly 0 and 1 among the depths. The
// edge functions' products reach 2^48 (exact in 64-bit integers and in double, not in float),
// and the plane is anchored 32768 pixels from the samples.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

float limitDepth(Rng& rng) {
  const long long k = rng.uniform(0, 3);
  return k == 0 ? 0.0f : (k == 1 ? 1.0f : rng.depth());
}

// One triangle with a long edge exactly through samples of the frame and its third vertex on
// the box.
void addLimitTriangle(Rng& rng, int w, int h, cmd::Draw& d) {
  constexpr long long L = kLimit;
  long long a[2], b[2], e[2];
  switch (rng.uniform(0, 3)) {
    case 0: {  // horizontal through row j
      const long long y = centre(rng.uniform(0, h - 1));
      a[0] = -L, a[1] = y, b[0] = L, b[1] = y;
      e[0] = rng.uniform(-L, L), e[1] = rng.chance(50) ? L : -L;
      break;
    }
    case 1: {  // vertical through column i
      const long long x = centre(rng.uniform(0, w - 1));
      a[0] = x, a[1] = -L, b[0] = x, b[1] = L;
      e[0] = rng.chance(50) ? L : -L, e[1] = rng.uniform(-L, L);
      break;
    }
    case 2: {  // X - Y = 256 k: through the samples (i, i - k)
      const long long k = rng.uniform(-(h - 1), w - 1);
      const long long off = 256 * k;
      a[0] = off > 0 ? -L + off : -L, a[1] = off > 0 ? -L : -L - off;
      b[0] = off > 0 ? L : L + off, b[1] = off > 0 ? L - off : L;
      e[0] = rng.chance(50) ? L : -L, e[1] = -e[0];
      break;
    }
    default: {  // corner to corner of the box, third vertex on an edge of it
      a[0] = -L, a[1] = rng.chance(50) ? -L : L;
      b[0] = L, b[1] = rng.uniform(-L, L);
      e[0] = rng.uniform(-L, L), e[1] = -a[1];
      break;
    }
  }
  const auto base = static_cast<std::uint32_t>(d.vertices.size());
  d.vertices.push_back(fixedVertex(a[0], a[1], limitDepth(rng)));
  d.vertices.push_back(fixedVertex(b[0], b[1], limitDepth(rng)));
  d.vertices.push_back(fixedVertex(e[0], e[1], limitDepth(rng)));
  const auto r = static_cast<std::uint32_t>(rng.uniform(0, 2));
  const bool flip = rng.chance(50);
  for (std::uint32_t k = 0; k < 3; ++k)
    d.indices.push_back(base + (r + (flip ? 3 - k : k)) % 3);
}

}  // namespace

Candidate limits(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::StrictLimits, Variant::FloatPlane,
                                     Variant::TopLeftFill, Variant::SwappedFacing};
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {kTargets[index % 4]};
  c.description =
      "Triangles with vertices at X, Y = +-2^23 (+-32768 pixels), edges exactly through "
      "sample points of the frame, depths 0 and 1 among others; stencil counts front and "
      "back fragments, depth keeps the last plane value.";
  c.commands = countFacingsKeepDepth();
  cmd::Draw d;
  const long long n = rng.uniform(1, 3);
  for (long long k = 0; k < n; ++k)
    addLimitTriangle(rng, c.width, c.height, d);
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
