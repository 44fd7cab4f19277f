#include "view_line_probe.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace recode::verify {

namespace {

// Twice the signed area of the projected triangle (a, b, c) on the (u, v) plane.
double area2(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

void widen(std::optional<AxisRange>& range, double d) {
  if (!range)
    range = AxisRange{d, d};
  range->lo = std::min(range->lo, d);
  range->hi = std::max(range->hi, d);
}

// Sutherland-Hodgman: keeps the part of `polygon` where sign * (coordinate k) >= sign * bound,
// interpolating along the polygon's edges in 3-D so every new point lies on the triangle.
std::vector<Eigen::Vector3d> clip(const std::vector<Eigen::Vector3d>& polygon, int k, double bound,
                                  double sign) {
  std::vector<Eigen::Vector3d> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    const double fa = sign * (a[k] - bound), fb = sign * (b[k] - bound);
    if (fa >= 0.0)
      out.push_back(a);
    if ((fa >= 0.0) != (fb >= 0.0)) {
      const double t = fa / (fa - fb);
      Eigen::Vector3d q = a + t * (b - a);
      q[k] = bound;  // exactly on the clipping line
      out.push_back(q);
    }
  }
  return out;
}

}  // namespace

ViewLineProbe::ViewLineProbe(const core::TriangleMesh& mesh, const core::OrthoView& view, double u0,
                             double v0, double u1, double v1) {
  std::vector<Eigen::Vector3d> plane;
  plane.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices)
    plane.push_back(view.toPlane(p));
  for (const core::Triangle& t : mesh.triangles) {
    for (const core::VertexIndex index : t)
      if (index >= plane.size())
        throw std::invalid_argument("a triangle indexes vertex " + std::to_string(index) +
                                    " of a mesh with " + std::to_string(plane.size()) +
                                    " vertices");
    PlaneTriangle pt{{plane[t[0]], plane[t[1]], plane[t[2]]}, 0, 0, 0, 0};
    pt.umin = std::min({pt.p[0].x(), pt.p[1].x(), pt.p[2].x()});
    pt.umax = std::max({pt.p[0].x(), pt.p[1].x(), pt.p[2].x()});
    pt.vmin = std::min({pt.p[0].y(), pt.p[1].y(), pt.p[2].y()});
    pt.vmax = std::max({pt.p[0].y(), pt.p[1].y(), pt.p[2].y()});
    if (pt.umax >= u0 && pt.umin <= u1 && pt.vmax >= v0 && pt.vmin <= v1)
      triangles_.push_back(pt);
  }
}

std::optional<AxisRange> ViewLineProbe::line(double u, double v) const {
  constexpr double kSlack = -1e-12;
  std::optional<AxisRange> range;
  const Eigen::Vector3d q(u, v, 0.0);
  for (const PlaneTriangle& t : triangles_) {
    if (u < t.umin || u > t.umax || v < t.vmin || v > t.vmax)
      continue;
    const double whole = area2(t.p[0], t.p[1], t.p[2]);
    if (whole == 0.0)
      continue;  // seen edge-on: its neighbours hold the same points on their edges
    const double w0 = area2(q, t.p[1], t.p[2]) / whole;
    const double w1 = area2(t.p[0], q, t.p[2]) / whole;
    const double w2 = area2(t.p[0], t.p[1], q) / whole;
    if (w0 < kSlack || w1 < kSlack || w2 < kSlack)
      continue;
    widen(range, w0 * t.p[0].z() + w1 * t.p[1].z() + w2 * t.p[2].z());
  }
  return range;
}

std::optional<AxisRange> ViewLineProbe::prism(double u0, double v0, double u1, double v1) const {
  std::optional<AxisRange> range;
  for (const PlaneTriangle& t : triangles_) {
    if (t.umax < u0 || t.umin > u1 || t.vmax < v0 || t.vmin > v1)
      continue;
    std::vector<Eigen::Vector3d> polygon(t.p.begin(), t.p.end());
    polygon = clip(polygon, 0, u0, 1.0);
    polygon = clip(polygon, 0, u1, -1.0);
    polygon = clip(polygon, 1, v0, 1.0);
    polygon = clip(polygon, 1, v1, -1.0);
    for (const Eigen::Vector3d& p : polygon)
      widen(range, p.z());
  }
  return range;
}

}  // namespace recode::verify
