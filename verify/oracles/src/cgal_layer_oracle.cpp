// The CGAL judge of the layered pair (docs/verification.md, "The layered pair against CGAL").
// The per-pixel judge is written from docs/rasterization.md alone (snapping, the fill rule, the
// plane through the snapped vertices), with the depth of each crossing an exact rational rather
// than the contract's rounded double: it shares no code with the devices.

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/pair/view.hpp"
#include "recode/raster/state.hpp"
#include "recode/verify/layer_oracle.hpp"

#include "cgal_exact_mesh.hpp"

namespace recode::verify {

namespace {

using Rational = cgal::Kernel::FT;
namespace PMP = CGAL::Polygon_mesh_processing;

// A triangle as the contract snaps it: 24.8 fixed-point x and y, the float depth exact.
struct SnappedTriangle {
  long long X[3], Y[3];
  Rational z[3];
};

// An integer of the coverage arithmetic as an exact rational: its magnitude stays below 2^53
// (docs/rasterization.md section 2 bounds it by 2^49), so the double holds it exactly.
Rational exactly(long long v) {
  return Rational(static_cast<double>(v));
}

long long snap(float v) {
  return static_cast<long long>(std::nearbyint(double{v} * 256.0));
}

// Section 4: a sample on an edge belongs to the triangle when the edge, directed
// counter-clockwise, runs downwards, or runs right along a horizontal.
bool inclusive(long long dx, long long dy) {
  return dy < 0 || (dy == 0 && dx > 0);
}

// Whether the triangle covers the sample (Xc, Yc), and its facing (sections 3 and 4).
bool covers(const SnappedTriangle& t, long long Xc, long long Yc, bool& front) {
  const long long a2 =
      (t.X[1] - t.X[0]) * (t.Y[2] - t.Y[0]) - (t.X[2] - t.X[0]) * (t.Y[1] - t.Y[0]);
  if (a2 == 0)
    return false;
  front = a2 > 0;
  const int order[3] = {0, front ? 1 : 2, front ? 2 : 1};
  for (int e = 0; e < 3; ++e) {
    const int i = order[e], j = order[(e + 1) % 3];
    const long long dx = t.X[j] - t.X[i], dy = t.Y[j] - t.Y[i];
    const long long E = dx * (Yc - t.Y[i]) - dy * (Xc - t.X[i]);
    if (E < 0 || (E == 0 && !inclusive(dx, dy)))
      return false;
  }
  return true;
}

// Section 5's plane through the snapped vertices, evaluated exactly at the sample.
Rational exactDepth(const SnappedTriangle& t, long long Xc, long long Yc) {
  const Rational dz1 = t.z[1] - t.z[0], dz2 = t.z[2] - t.z[0];
  const Rational e1x = exactly(t.X[1] - t.X[0]), e1y = exactly(t.Y[1] - t.Y[0]);
  const Rational e2x = exactly(t.X[2] - t.X[0]), e2y = exactly(t.Y[2] - t.Y[0]);
  const Rational a2 = e1x * e2y - e2x * e1y;
  const Rational dzdx = (dz1 * e2y - dz2 * e1y) / a2;
  const Rational dzdy = (dz2 * e1x - dz1 * e2x) / a2;
  return t.z[0] + dzdx * exactly(Xc - t.X[0]) + dzdy * exactly(Yc - t.Y[0]);
}

// Every crossing of the MOR's pixel-centre lines with one mesh: entries and exits per pixel.
struct MeshCrossings {
  std::vector<std::vector<Rational>> entries, exits;  // indexed by MOR pixel
};

MeshCrossings crossingsOf(const core::TriangleMesh& mesh, const core::OrthoView& view,
                          const raster::PixelRect& mor) {
  MeshCrossings c;
  c.entries.resize(static_cast<std::size_t>(mor.area()));
  c.exits.resize(static_cast<std::size_t>(mor.area()));
  for (const core::Triangle& tri : mesh.triangles) {
    SnappedTriangle t;
    for (int k = 0; k < 3; ++k) {
      const raster::WindowVertex v = view.toWindow(mesh.vertices[tri[static_cast<std::size_t>(k)]]);
      t.X[k] = snap(v.x);
      t.Y[k] = snap(v.y);
      t.z[k] = Rational(double{v.z});
    }
    // The pixels whose centres 256 i + 128 lie in the triangle's box, within the MOR.
    const auto first = [](long long lo) {
      return static_cast<int>(std::ceil((static_cast<double>(lo) - 128.0) / 256.0));
    };
    const auto last = [](long long hi) {
      return static_cast<int>(std::floor((static_cast<double>(hi) - 128.0) / 256.0));
    };
    const int x0 = std::max(mor.x0, first(std::min({t.X[0], t.X[1], t.X[2]})));
    const int x1 = std::min(mor.x1 - 1, last(std::max({t.X[0], t.X[1], t.X[2]})));
    const int y0 = std::max(mor.y0, first(std::min({t.Y[0], t.Y[1], t.Y[2]})));
    const int y1 = std::min(mor.y1 - 1, last(std::max({t.Y[0], t.Y[1], t.Y[2]})));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const long long Xc = 256LL * x + 128, Yc = 256LL * y + 128;
        bool front = false;
        if (!covers(t, Xc, Yc, front))
          continue;
        const auto at = static_cast<std::size_t>((y - mor.y0) * mor.width() + (x - mor.x0));
        (front ? c.entries : c.exits)[at].push_back(exactDepth(t, Xc, Yc));
      }
  }
  return c;
}

struct ExactInterval {
  Rational lo, hi;
};

// The depths inside a mesh at a pixel: sorted entries paired with sorted exits, merged.
std::vector<ExactInterval> inside(std::vector<Rational> entries, std::vector<Rational> exits) {
  if (entries.size() != exits.size())
    throw std::logic_error("layer judge: a pixel-centre line enters a mesh " +
                           std::to_string(entries.size()) + " times and leaves it " +
                           std::to_string(exits.size()) + " times");
  std::sort(entries.begin(), entries.end());
  std::sort(exits.begin(), exits.end());
  std::vector<ExactInterval> out;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Rational lo = std::min(entries[i], exits[i]), hi = std::max(entries[i], exits[i]);
    if (!out.empty() && lo <= out.back().hi)
      out.back().hi = std::max(out.back().hi, hi);
    else
      out.push_back({lo, hi});
  }
  return out;
}

bool meet(const std::vector<ExactInterval>& a, const std::vector<ExactInterval>& b) {
  for (const ExactInterval& p : a)
    for (const ExactInterval& q : b)
      if (std::max(p.lo, q.lo) <= std::min(p.hi, q.hi))
        return true;
  return false;
}

// Whether two of the pixel's crossings lie within kLayerTieSteps of each other.
bool hasTie(const MeshCrossings& a, const MeshCrossings& b, std::size_t at) {
  std::vector<Rational> all;
  for (const MeshCrossings* m : {&a, &b})
    for (const auto* list : {&m->entries[at], &m->exits[at]})
      all.insert(all.end(), list->begin(), list->end());
  std::sort(all.begin(), all.end());
  const Rational window = Rational(kLayerTieSteps) / Rational(double{raster::kDepthMax});
  for (std::size_t i = 1; i < all.size(); ++i)
    if (all[i] - all[i - 1] <= window)
      return true;
  return false;
}

}  // namespace

LayerPixelJudgement judgeLayeredPixels(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                       const core::FrameSpec& frame,
                                       const core::LayeredPairResult& result) {
  LayerPixelJudgement j;
  if (result.mor.empty())
    return j;
  if (result.interferes.rect != result.mor)
    throw std::invalid_argument(
        "judgeLayeredPixels: the result kept no pixels (run it with PairRequest::keepPixels)");
  const core::OrthoView view(frame.axis, frame.window, frame.width, frame.height, result.depthMin,
                             result.depthMax);
  const raster::PixelRect& mor = result.mor;
  const MeshCrossings ca = crossingsOf(a, view, mor), cb = crossingsOf(b, view, mor);
  for (int y = mor.y0; y < mor.y1; ++y)
    for (int x = mor.x0; x < mor.x1; ++x) {
      const auto at = static_cast<std::size_t>((y - mor.y0) * mor.width() + (x - mor.x0));
      const bool exact =
          meet(inside(ca.entries[at], ca.exits[at]), inside(cb.entries[at], cb.exits[at]));
      const bool device = result.interferes.at(x, y) != 0;
      ++j.pixels;
      j.exactInterfering += exact ? 1 : 0;
      if (exact == device) {
        ++j.agreed;
      } else if (hasTie(ca, cb, at)) {
        ++j.ties;
      } else {
        ++j.disagreed;
        if (j.firstDisagreements.size() < 16)
          j.firstDisagreements.push_back({x, y});
      }
    }
  return j;
}

bool closedMeshesMeet(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  const cgal::ExactMesh ea = cgal::toExactMesh(a, "mesh A"), eb = cgal::toExactMesh(b, "mesh B");
  return PMP::do_intersect(ea, eb, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                           CGAL::parameters::do_overlap_test_of_bounded_sides(true));
}

bool closedSurfacesMeet(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  const cgal::ExactMesh ea = cgal::toExactMesh(a, "mesh A"), eb = cgal::toExactMesh(b, "mesh B");
  return PMP::do_intersect(ea, eb);
}

double closedMeshesOverlapVolume(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  cgal::ExactMesh ea = cgal::toExactMesh(a, "mesh A"), eb = cgal::toExactMesh(b, "mesh B");
  cgal::ExactMesh out;
  if (!PMP::corefine_and_compute_intersection(ea, eb, out))
    throw std::runtime_error("CGAL's corefinement could not build the intersection of the meshes");
  if (out.number_of_faces() == 0)
    return 0.0;
  return CGAL::to_double(PMP::volume(out));
}

}  // namespace recode::verify
