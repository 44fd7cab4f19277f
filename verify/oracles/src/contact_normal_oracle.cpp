#include "recode/verify/contact_normal_oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace recode::verify {

namespace {

// Cross products shorter than this (relative to the edges' lengths) are of parallel edges and
// name no direction.
constexpr double kParallel = 1e-12;

std::vector<Eigen::Vector3d> faceNormals(const core::TriangleMesh& m) {
  std::vector<Eigen::Vector3d> out;
  for (const core::Triangle& t : m.triangles) {
    const Eigen::Vector3d n =
        (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
    if (n.norm() > 0.0)
      out.push_back(n.normalized());
  }
  return out;
}

// Unit edge directions, each undirected edge once.
std::vector<Eigen::Vector3d> edgeDirections(const core::TriangleMesh& m) {
  std::set<std::pair<core::VertexIndex, core::VertexIndex>> seen;
  std::vector<Eigen::Vector3d> out;
  for (const core::Triangle& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const core::VertexIndex i = t[static_cast<std::size_t>(k)];
      const core::VertexIndex j = t[static_cast<std::size_t>((k + 1) % 3)];
      if (!seen.insert(std::minmax(i, j)).second)
        continue;
      const Eigen::Vector3d e = m.vertices[j] - m.vertices[i];
      if (e.norm() > 0.0)
        out.push_back(e.normalized());
    }
  }
  return out;
}

std::array<double, 2> spread(const core::TriangleMesh& m, const Eigen::Vector3d& d) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector3d& p : m.vertices) {
    lo = std::min(lo, p.dot(d));
    hi = std::max(hi, p.dot(d));
  }
  return {lo, hi};
}

Eigen::Vector3d largestComponentPositive(const Eigen::Vector3d& d) {
  Eigen::Index k = 0;
  d.cwiseAbs().maxCoeff(&k);
  return d[k] < 0.0 ? Eigen::Vector3d(-d) : d;
}

// Calls f on every face normal of both meshes and every cross product of an edge of `a` with an
// edge of `b` (unit length).
template <class F>
void forCandidates(const core::TriangleMesh& a, const core::TriangleMesh& b, F&& f) {
  for (const Eigen::Vector3d& n : faceNormals(a))
    f(n);
  for (const Eigen::Vector3d& n : faceNormals(b))
    f(n);
  const std::vector<Eigen::Vector3d> ea = edgeDirections(a);
  const std::vector<Eigen::Vector3d> eb = edgeDirections(b);
  for (const Eigen::Vector3d& u : ea) {
    for (const Eigen::Vector3d& v : eb) {
      const Eigen::Vector3d c = u.cross(v);
      if (c.norm() > kParallel)
        f(c.normalized());
    }
  }
}

}  // namespace

OracleDirection thinnestDirectionOf(const core::TriangleMesh& solid) {
  OracleDirection best;
  best.extent = std::numeric_limits<double>::infinity();
  forCandidates(solid, solid, [&](const Eigen::Vector3d& d) {
    const auto [lo, hi] = spread(solid, d);
    if (hi - lo < best.extent)
      best = {largestComponentPositive(d), hi - lo};
  });
  if (best.direction.isZero())
    best.extent = 0.0;
  return best;
}

OracleDirection penetrationNormal(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  OracleDirection best;
  best.extent = std::numeric_limits<double>::infinity();
  forCandidates(a, b, [&](const Eigen::Vector3d& d) {
    const auto [aLo, aHi] = spread(a, d);
    const auto [bLo, bHi] = spread(b, d);
    // Moving B along +d by aHi - bLo separates the blocks; along -d, by bHi - aLo.
    if (aHi - bLo < best.extent)
      best = {d, aHi - bLo};
    if (bHi - aLo < best.extent)
      best = {-d, bHi - aLo};
  });
  if (best.direction.isZero())
    best.extent = 0.0;
  return best;
}

double angleDegrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const double c = u.normalized().dot(v.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

}  // namespace recode::verify
