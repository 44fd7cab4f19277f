#include "embree_window_block.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace recode::verify::detail {

namespace {

// Squares of fixed-point distances reach 2^98 (coordinates up to 2^23 units, so differences
// up to 2^24 and cross products up to 2^49): beyond 64 bits, so the edge test squares in 128.
__extension__ using Int128 = __int128;

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

// Whether point p lies within one fixed-point unit of the segment a-b (a point if a == b).
bool withinOneUnit(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                   std::int64_t px, std::int64_t py) {
  const std::int64_t dx = bx - ax, dy = by - ay, qx = px - ax, qy = py - ay;
  const std::int64_t along = dx * qx + dy * qy;
  const std::int64_t length2 = dx * dx + dy * dy;
  if (along <= 0)
    return qx * qx + qy * qy <= 1;
  if (along >= length2) {
    const std::int64_t rx = px - bx, ry = py - by;
    return rx * rx + ry * ry <= 1;
  }
  // Inside the segment's span: distance = |cross| / length, compared squared and exactly.
  const Int128 cross = Int128{dx} * qy - Int128{dy} * qx;
  return cross * cross <= Int128{length2};
}

}  // namespace

WindowBlock makeWindowBlock(const core::OrthoView& view, const core::TriangleMesh& mesh,
                            const char* name) {
  WindowBlock block;
  const std::size_t n = mesh.vertices.size();
  block.fx.reserve(n);
  block.fy.reserve(n);
  block.x.reserve(n);
  block.y.reserve(n);
  block.zf.reserve(n);
  block.z.reserve(n);
  const double range = view.depthMax() - view.depthMin();
  for (const Eigen::Vector3d& p : mesh.vertices) {
    // The device's vertex (snapped x and y, float depth); it also rejects unmappable points.
    const raster::WindowVertex v = view.toWindow(p);
    block.x.push_back(v.x);
    block.y.push_back(v.y);
    block.zf.push_back(v.z);
    block.fx.push_back(static_cast<std::int64_t>(std::nearbyint(double{v.x} * 256.0)));
    block.fy.push_back(static_cast<std::int64_t>(std::nearbyint(double{v.y} * 256.0)));
    // The same depth mapping, kept in double: the oracle's depths carry no float rounding.
    block.z.push_back((view.depthMax() - view.toPlane(p).z()) / range);
  }
  block.triangles = mesh.triangles;
  block.area2.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const core::Triangle& tri = mesh.triangles[t];
    for (const core::VertexIndex i : tri) {
      if (i >= n) {
        std::ostringstream m;
        m << "block " << name << ": triangle " << t << " uses vertex " << i << " but the mesh has "
          << n << " vertices";
        throw std::invalid_argument(m.str());
      }
    }
    const std::int64_t e1x = block.fx[tri[1]] - block.fx[tri[0]];
    const std::int64_t e1y = block.fy[tri[1]] - block.fy[tri[0]];
    const std::int64_t e2x = block.fx[tri[2]] - block.fx[tri[0]];
    const std::int64_t e2y = block.fy[tri[2]] - block.fy[tri[0]];
    block.area2.push_back(e1x * e2y - e2x * e1y);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = tri[static_cast<std::size_t>(k)];
      const std::uint32_t j = tri[static_cast<std::size_t>((k + 1) % 3)];
      block.edges.push_back({std::min(i, j), std::max(i, j)});
    }
  }
  std::sort(block.edges.begin(), block.edges.end());
  block.edges.erase(std::unique(block.edges.begin(), block.edges.end()), block.edges.end());
  return block;
}

namespace {

// The three edge functions of triangle t at p, each positive on the interior side of a
// counter-clockwise triangle; their sum is area2. Index k belongs to the edge opposite
// vertex k, so w[k] / area2 is vertex k's barycentric weight.
std::array<std::int64_t, 3> edgeWeights(const WindowBlock& b, std::size_t t, std::int64_t px,
                                        std::int64_t py) {
  const core::Triangle& tri = b.triangles[t];
  std::array<std::int64_t, 3> w{};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t i = tri[(k + 1) % 3], j = tri[(k + 2) % 3];
    w[k] = (b.fx[j] - b.fx[i]) * (py - b.fy[i]) - (b.fy[j] - b.fy[i]) * (px - b.fx[i]);
  }
  return w;
}

}  // namespace

bool covers(const WindowBlock& block, std::size_t t, std::int64_t px, std::int64_t py) {
  const std::int64_t a2 = block.area2[t];
  if (a2 == 0)
    return false;
  const std::array<std::int64_t, 3> w = edgeWeights(block, t, px, py);
  if (a2 > 0)
    return w[0] >= 0 && w[1] >= 0 && w[2] >= 0;
  return w[0] <= 0 && w[1] <= 0 && w[2] <= 0;
}

double depthAt(const WindowBlock& block, std::size_t t, std::int64_t px, std::int64_t py) {
  // The weights are exact integers below 2^50, hence exact in double: the only roundings are
  // the three products, their sum and the division, a few parts in 1e16 of the depth.
  const std::array<std::int64_t, 3> w = edgeWeights(block, t, px, py);
  const core::Triangle& tri = block.triangles[t];
  const double sum = static_cast<double>(w[0]) * block.z[tri[0]] +
                     static_cast<double>(w[1]) * block.z[tri[1]] +
                     static_cast<double>(w[2]) * block.z[tri[2]];
  return sum / static_cast<double>(block.area2[t]);
}

std::optional<std::array<double, 2>> bruteForceInterval(const WindowBlock& block, std::int64_t px,
                                                        std::int64_t py) {
  std::optional<std::array<double, 2>> interval;
  for (std::size_t t = 0; t < block.triangles.size(); ++t) {
    if (!covers(block, t, px, py))
      continue;
    const double z = depthAt(block, t, px, py);
    if (!interval)
      interval = std::array<double, 2>{z, z};
    else
      interval = std::array<double, 2>{std::min((*interval)[0], z), std::max((*interval)[1], z)};
  }
  return interval;
}

bool nearProjectedEdge(const WindowBlock& block, std::int64_t px, std::int64_t py) {
  for (const auto& [i, j] : block.edges) {
    const std::int64_t ax = block.fx[i], ay = block.fy[i], bx = block.fx[j], by = block.fy[j];
    // Cheap rejection by the segment's box grown by one unit.
    if (px < std::min(ax, bx) - 1 || px > std::max(ax, bx) + 1 || py < std::min(ay, by) - 1 ||
        py > std::max(ay, by) + 1)
      continue;
    if (withinOneUnit(ax, ay, bx, by, px, py))
      return true;
  }
  return false;
}

raster::PixelRect footprint(const WindowBlock& block, int width, int height) {
  if (block.fx.empty())
    return {};
  const auto [xlo, xhi] = std::minmax_element(block.fx.begin(), block.fx.end());
  const auto [ylo, yhi] = std::minmax_element(block.fy.begin(), block.fy.end());
  // Centre 256 i + 128 >= lo  <=>  i >= ceil((lo - 128) / 256); <= hi  <=>  i <= floor(...).
  const auto first = [](std::int64_t lo) {
    return -floorDiv(-(lo - raster::kSubpixelOne / 2), raster::kSubpixelOne);
  };
  const auto last = [](std::int64_t hi) {
    return floorDiv(hi - raster::kSubpixelOne / 2, raster::kSubpixelOne) + 1;
  };
  const auto clamp = [](std::int64_t v, int hi) {
    return static_cast<int>(std::clamp<std::int64_t>(v, 0, hi));
  };
  return raster::PixelRect{clamp(first(*xlo), width), clamp(first(*ylo), height),
                           clamp(last(*xhi), width), clamp(last(*yhi), height)};
}

std::uint32_t quantiseDepth(double z) {
  if (!(z > 0.0))
    return 0;
  if (z >= 1.0)
    return raster::kDepthMax;
  return static_cast<std::uint32_t>(std::nearbyint(z * static_cast<double>(raster::kDepthMax)));
}

}  // namespace recode::verify::detail
