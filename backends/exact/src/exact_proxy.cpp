#include "recode/backends/exact_proxy.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "recode/raster/device_checks.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::backends {

namespace {

// Rows per band when a triangle's rectangle is split (see proxyRects).
constexpr int kBandRows = 4;

// The columns whose pixel centres can lie in the triangle within the rows [row0, row1): the
// triangle cut by the slab between those rows' centre lines is a convex polygon whose corners
// are the triangle's corners inside the slab and the edges' crossings of its two lines, so its
// x-extent bounds every covered centre of those rows. Crossings are found in double from the
// 24.8 fixed-point corners (exact up to one rounding of a division) and widened by 2/256 pixel,
// so no centre the contract covers is left out. Returns an empty range when the slab misses the
// triangle.
struct ColumnRange {
  int x0 = 0, x1 = 0;  // half-open
};

ColumnRange columnsInRows(const raster::FixedVertex (&v)[3], int row0, int row1) {
  const double ylo = (row0 + 0.5) * 256.0;
  const double yhi = (row1 - 0.5) * 256.0;
  double xmin = std::numeric_limits<double>::infinity();
  double xmax = -xmin;
  const auto add = [&](double x) {
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
  };
  for (int i = 0; i < 3; ++i) {
    const raster::FixedVertex& a = v[i];
    const raster::FixedVertex& b = v[(i + 1) % 3];
    const auto ay = static_cast<double>(a.y), by = static_cast<double>(b.y);
    if (ay >= ylo && ay <= yhi)
      add(static_cast<double>(a.x));
    if (a.y == b.y)
      continue;
    for (const double y : {ylo, yhi}) {
      if (y < std::min(ay, by) || y > std::max(ay, by))
        continue;
      add(static_cast<double>(a.x) +
          (y - ay) * static_cast<double>(b.x - a.x) / static_cast<double>(b.y - a.y));
    }
  }
  if (!(xmin <= xmax))
    return {};
  // Centre of column i is (i + 0.5) * 256: i from ceil(xmin / 256 - 0.5) to
  // floor(xmax / 256 - 0.5).
  const double margin = 2.0;
  return {static_cast<int>(std::ceil((xmin - margin) / 256.0 - 0.5)),
          static_cast<int>(std::floor((xmax + margin) / 256.0 - 0.5)) + 1};
}

// Whether splitting the rectangle into bands pays: it is tall, and much larger than the
// triangle (a sliver's rectangle can be hundreds of times its area; every pixel of a proxy
// costs the GPU a fragment of the contract's shader).
bool worthBanding(const raster::PixelRect& rect, const raster::FixedVertex (&v)[3]) {
  if (rect.height() <= 2 * kBandRows)
    return false;
  const double twiceArea =
      std::abs(static_cast<double>(v[1].x - v[0].x) * static_cast<double>(v[2].y - v[0].y) -
               static_cast<double>(v[2].x - v[0].x) * static_cast<double>(v[1].y - v[0].y)) /
      65536.0;
  const double perimeterBand = 2.0 * (rect.width() + rect.height());
  return static_cast<double>(rect.area()) > twiceArea + perimeterBand;
}

}  // namespace

std::vector<ProxyTriangle> buildProxyTriangles(std::span<const raster::WindowVertex> vertices,
                                               std::span<const std::uint32_t> indices,
                                               const raster::RenderState& state) {
  std::vector<ProxyTriangle> proxies;
  buildProxyTrianglesInto(vertices, indices, state, proxies);
  return proxies;
}

void buildProxyTrianglesInto(std::span<const raster::WindowVertex> vertices,
                             std::span<const std::uint32_t> indices,
                             const raster::RenderState& state,
                             std::vector<ProxyTriangle>& proxies) {
  raster::checkDraw(vertices, indices);
  proxies.clear();
  proxies.reserve(indices.size() / 3);
  for (std::size_t k = 0; k + 2 < indices.size(); k += 3) {
    const raster::FixedVertex v[3] = {raster::snapVertex(vertices[indices[k]]),
                                      raster::snapVertex(vertices[indices[k + 1]]),
                                      raster::snapVertex(vertices[indices[k + 2]])};
    // The whole setup, depth plane included: its two correctly rounded divisions are done here
    // once per triangle rather than in the vertex stage four times per proxy.
    const auto setup = raster::setupTriangle(v[0], v[1], v[2]);
    if (!setup || state.culls(setup->frontFacing))
      continue;
    const raster::PixelRect rect = setup->bounds.intersect(state.scissor);
    if (rect.empty())
      continue;
    ProxyTriangle p{};
    for (int i = 0; i < 3; ++i) {
      // checkDraw bounds |x|, |y| by 32768 pixels, so the fixed-point values fit 24 bits.
      std::int32_t* xy = i < 2 ? &p.fixedV0V1[2 * i] : p.fixedV2;
      xy[0] = static_cast<std::int32_t>(v[i].x);
      xy[1] = static_cast<std::int32_t>(v[i].y);
      p.z[i] = v[i].z;
    }
    p.frontFacing = setup->frontFacing ? 1 : 0;
    std::memcpy(&p.slopeBits[0], &setup->depth.dzdx, sizeof(double));
    std::memcpy(&p.slopeBits[2], &setup->depth.dzdy, sizeof(double));
    const auto emit = [&](const raster::PixelRect& r) {
      if (r.empty())
        return;
      p.pixelRect[0] = r.x0;
      p.pixelRect[1] = r.y0;
      p.pixelRect[2] = r.x1;
      p.pixelRect[3] = r.y1;
      proxies.push_back(p);
    };
    if (!worthBanding(rect, v)) {
      emit(rect);
      continue;
    }
    // Bands of rows, bottom up, each over the columns the triangle can cover in its rows: every
    // pixel lies in one band, so the triangle still reaches each pixel once, and its bands are
    // consecutive records, so triangles still reach each pixel in index order.
    for (int y0 = rect.y0; y0 < rect.y1; y0 += kBandRows) {
      const int y1 = std::min(y0 + kBandRows, rect.y1);
      const ColumnRange c = columnsInRows(v, y0, y1);
      emit(raster::PixelRect{c.x0, y0, c.x1, y1}.intersect(rect));
    }
  }
}

}  // namespace recode::backends
