// The clipping freedom (api_freedoms.hpp) is wide enough and needed: a pipeline that clips every
// triangle reaching beyond the guaranteed viewport bounds to a guard band, in single precision,
// and draws the clipped polygon's fan under the contract, stays inside the allowed states at
// every pixel, at guard bands from none to 8192 pixels, on the kit's vectors with such triangles
// and on random streams of the limits family; without the freedom it falls outside.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "recode/conformance/api_freedoms.hpp"
#include "recode/conformance/backend.hpp"
#include "recode/conformance/suite.hpp"

using namespace recode;
using namespace recode::conformance;
namespace cmd = recode::raster::cmd;

namespace {

struct Point {
  float x, y, z;  // window coordinates in NDC on x and y while clipping
};

// One of the four planes of the clip rectangle |x| <= limitX, |y| <= limitY (NDC), as the
// signed distance of a point inside it, in float.
float distance(const Point& p, int plane, float limitX, float limitY) {
  switch (plane) {
    case 0:
      return limitX + p.x;
    case 1:
      return limitX - p.x;
    case 2:
      return limitY + p.y;
    default:
      return limitY - p.y;
  }
}

// Sutherland-Hodgman against one plane, every operation in float: new vertices P0 + t (P1 - P0)
// with t = d0 / (d0 - d1), depths interpolated alike.
std::vector<Point> clipAgainst(const std::vector<Point>& in, int plane, float lx, float ly) {
  std::vector<Point> out;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Point& a = in[i];
    const Point& b = in[(i + 1) % in.size()];
    const float da = distance(a, plane, lx, ly);
    const float db = distance(b, plane, lx, ly);
    if (da >= 0.0f)
      out.push_back(a);
    if ((da >= 0.0f) != (db >= 0.0f)) {
      const float t = da / (da - db);
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
    }
  }
  return out;
}

bool beyondBounds(const raster::WindowVertex& v, const ViewportBounds& b) {
  return v.x < b.lo || v.x > b.hi || v.y < b.lo || v.y > b.hi;
}

// The stream as a pipeline that clips draws it: each triangle with a vertex beyond the
// guaranteed bounds carried to NDC, clipped to the frame grown by `band` pixels and carried back
// to window coordinates, all in float, then drawn as the fan of the clipped polygon.
raster::CommandStream clippedInFloat(const raster::CommandStream& s, float band) {
  raster::CommandStream out = s;
  const ViewportBounds bounds = guaranteedBounds(std::max(s.width, s.height));
  const float hw = static_cast<float>(s.width) * 0.5f;
  const float hh = static_cast<float>(s.height) * 0.5f;
  const float lx = 1.0f + band / hw;
  const float ly = 1.0f + band / hh;
  for (raster::Command& c : out.commands) {
    auto* d = std::get_if<cmd::Draw>(&c);
    if (d == nullptr)
      continue;
    cmd::Draw next;
    for (std::size_t t = 0; t + 2 < d->indices.size(); t += 3) {
      const raster::WindowVertex v[3] = {d->vertices[d->indices[t]], d->vertices[d->indices[t + 1]],
                                         d->vertices[d->indices[t + 2]]};
      const auto base = static_cast<std::uint32_t>(next.vertices.size());
      if (!beyondBounds(v[0], bounds) && !beyondBounds(v[1], bounds) &&
          !beyondBounds(v[2], bounds)) {
        next.vertices.insert(next.vertices.end(), v, v + 3);
        next.indices.insert(next.indices.end(), {base, base + 1, base + 2});
        continue;
      }
      std::vector<Point> poly;
      for (const raster::WindowVertex& w : v)
        poly.push_back({w.x / hw - 1.0f, w.y / hh - 1.0f, w.z});
      for (int plane = 0; plane < 4 && !poly.empty(); ++plane)
        poly = clipAgainst(poly, plane, lx, ly);
      if (poly.size() < 3)
        continue;
      for (const Point& p : poly)
        next.vertices.push_back(
            {(p.x + 1.0f) * hw, (p.y + 1.0f) * hh, std::clamp(p.z, 0.0f, 1.0f)});
      for (std::uint32_t k = 1; k + 1 < poly.size(); ++k)
        next.indices.insert(next.indices.end(), {base, base + k, base + k + 1});
    }
    *d = std::move(next);
  }
  return out;
}

bool reachesBeyondBounds(const raster::CommandStream& s) {
  const ViewportBounds bounds = guaranteedBounds(std::max(s.width, s.height));
  for (const raster::Command& c : s.commands)
    if (const auto* d = std::get_if<cmd::Draw>(&c))
      for (const raster::WindowVertex& v : d->vertices)
        if (beyondBounds(v, bounds))
          return true;
  return false;
}

// The golden vectors with a triangle beyond the bounds, and random streams of the limits family.
const std::vector<SuiteVector>& hugeTriangles() {
  static const std::vector<SuiteVector> all = [] {
    std::vector<SuiteVector> out;
    for (SuiteVector& v : goldenVectors(RECODE_DATA_DIR "/golden"))
      if (reachesBeyondBounds(v.golden.stream))
        out.push_back(std::move(v));
    for (SuiteVector& v : randomVectors(300, 5, "limits"))
      out.push_back(std::move(v));
    return out;
  }();
  return all;
}

// Pixels of the clipping pipeline's answer outside the allowed states, over every vector.
long long outsideAllowed(float band, const FreedomWidths& widths, std::string* first) {
  long long bad = 0;
  for (const SuiteVector& v : hugeTriangles()) {
    const raster::CommandStream& s = v.golden.stream;
    const Answer got = referenceAnswer(clippedInFloat(s, band));
    const AllowedFrame frame = allowedByApis(s, widths);
    for (std::size_t p = 0; p < frame.pixels.size(); ++p) {
      if (frame.pixels[p].allows(got.depth[p], got.stencil[p]))
        continue;
      if (bad++ == 0 && first != nullptr)
        *first = v.name + " pixel " + std::to_string(p) + ": depth " +
                 std::to_string(got.depth[p]) + ", stencil " + std::to_string(got.stencil[p]);
    }
  }
  return bad;
}

constexpr float kGuardBands[] = {0.0f, 4.0f, 64.0f, 1024.0f, 8192.0f};

}  // namespace

TEST_CASE("the vectors with triangles beyond the viewport bounds are there", "[clipping]") {
  // The kit's limits family and its 65536-pixel triangle, and the random streams.
  CHECK(hugeTriangles().size() > 300);
}

TEST_CASE("a pipeline that clips in float stays inside the allowed states", "[clipping]") {
  for (const float band : kGuardBands) {
    std::string first;
    const long long bad = outsideAllowed(band, {}, &first);
    INFO("guard band " << band << " pixels; first outside: " << first);
    CHECK(bad == 0);
  }
}

TEST_CASE("without the clipping freedom a pipeline that clips falls outside", "[clipping]") {
  FreedomWidths noClipping;
  noClipping.clipping = false;
  long long bad = 0;
  for (const float band : kGuardBands)
    bad += outsideAllowed(band, noClipping, nullptr);
  CHECK(bad > 0);
}
