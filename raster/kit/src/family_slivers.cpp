// Slivers: triangles a few 1/256 pixel wide whose long edge runs exactly through sample points,
// horizontally (where the bottom-left and top-left rules part), vertically, diagonally, or from
// thousands of pixels away (steep planes anchored far from the samples).
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

// A long edge through the sample of pixel (i, j), and a third vertex `width` sub-pixel steps
// to one side of its middle.
void addSliver(Rng& rng, int w, int h, std::vector<WindowVertex>& v,
               std::vector<std::uint32_t>& idx) {
  const long long cx = centre(rng.uniform(0, w - 1)), cy = centre(rng.uniform(0, h - 1));
  long long dx = 0, dy = 0, reach = 0;
  switch (rng.uniform(0, 3)) {
    case 0:
      dx = 256, reach = rng.uniform(2, w);  // horizontal
      break;
    case 1:
      dy = 256, reach = rng.uniform(2, h);  // vertical
      break;
    case 2:
      dx = 256 * rng.uniform(-3, 3), dy = 256 * rng.uniform(1, 3), reach = rng.uniform(1, 4);
      break;
    default:  // from far away: a direction of many sub-pixel steps, thousands of pixels long
      dx = rng.uniform(-900, 900), dy = rng.uniform(1, 900), reach = rng.uniform(300, 2000);
      break;
  }
  const long long back = rng.uniform(1, reach);
  const long long ax = cx - back * dx, ay = cy - back * dy;
  const long long bx = cx + reach * dx, by = cy + reach * dy;
  const long long width = rng.uniform(1, 3) * (rng.chance(50) ? 1 : -1);
  const bool mostlyHorizontal = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const long long mx = (ax + bx) / 2 + (mostlyHorizontal ? 0 : width);
  const long long my = (ay + by) / 2 + (mostlyHorizontal ? width : 0);
  const auto base = static_cast<std::uint32_t>(v.size());
  v.push_back(fixedVertex(ax, ay, rng.depth()));
  v.push_back(fixedVertex(bx, by, rng.depth()));
  v.push_back(fixedVertex(mx, my, rng.depth()));
  // Either winding, submitted from any vertex.
  const std::uint32_t r = static_cast<std::uint32_t>(rng.uniform(0, 2));
  const bool flip = rng.chance(50);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t corner = (r + (flip ? 3 - k : k)) % 3;
    idx.push_back(base + corner);
  }
}

}  // namespace

Candidate slivers(Rng& rng, int index) {
  static const Variant kTargets[] = {Variant::TopLeftFill, Variant::FloatPlane,
                                     Variant::SwappedFacing};
  Candidate c;
  c.width = 24;
  c.height = 16;
  c.targets = {kTargets[index % 3]};
  c.description =
      "Slivers 1-3/256 pixel wide whose long edges pass exactly through sample points "
      "(horizontal, vertical, diagonal, or from up to 2000 pixels away), both windings; "
      "stencil counts front (+1) and back (-1) fragments, depth keeps the last plane value.";
  c.commands = countFacingsKeepDepth();
  cmd::Draw d;
  const long long n = rng.uniform(3, 6);
  for (long long k = 0; k < n; ++k)
    addSliver(rng, c.width, c.height, d.vertices, d.indices);
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
