// Shared edges: a grid of cells, each split along a random diagonal, with grid lines through
// pixel centres (some interior points moved half a pixel), triangles of either winding and
// submitted from any corner: each sample once, on whichever side owns the shared edge.
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

Candidate sharedEdges(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::TopLeftFill, Variant::SwappedFacing};
  Candidate c;
  c.width = 20;
  c.height = 20;
  c.targets = {kTargets[index % 2]};
  c.description =
      "A triangulated grid whose shared edges pass through sample points, random diagonals, "
      "windings and first vertices: every sample inside once (stencil 1 front, 255 back), "
      "depth from the plane of the triangle that owns it.";
  c.commands = countFacingsKeepDepth();
  const int m = static_cast<int>(rng.uniform(2, 5)), n = static_cast<int>(rng.uniform(2, 5));
  const long long step = rng.uniform(2, 4), x0 = rng.uniform(0, 3), y0 = rng.uniform(0, 3);
  cmd::Draw d;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= m; ++i) {
      long long X = centre(x0 + i * step), Y = centre(y0 + j * step);
      const bool interior = i > 0 && i < m && j > 0 && j < n;
      if (interior && rng.chance(30)) {
        X += 128 * rng.uniform(-1, 1);
        Y += 128 * rng.uniform(-1, 1);
      }
      d.vertices.push_back(fixedVertex(X, Y, rng.depth()));
    }
  }
  const auto at = [m](int i, int j) { return static_cast<std::uint32_t>(j * (m + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < m; ++i) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), e = at(i + 1, j + 1), f = at(i, j + 1);
      std::uint32_t tris[2][3];
      if (rng.chance(50)) {
        tris[0][0] = a, tris[0][1] = b, tris[0][2] = e;
        tris[1][0] = a, tris[1][1] = e, tris[1][2] = f;
      } else {
        tris[0][0] = a, tris[0][1] = b, tris[0][2] = f;
        tris[1][0] = b, tris[1][1] = e, tris[1][2] = f;
      }
      for (auto& t : tris) {
        if (rng.chance(50))
          std::swap(t[1], t[2]);
        const auto r = static_cast<std::uint32_t>(rng.uniform(0, 2));
        for (std::uint32_t k = 0; k < 3; ++k)
          d.indices.push_back(t[(r + k) % 3]);
      }
    }
  }
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
