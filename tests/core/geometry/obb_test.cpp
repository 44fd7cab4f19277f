// Oriented bounding boxes: fitting contains the points and finds a rotated box's own axes;
// the 15-axis separating-axis test agrees with a brute-force intersection test of the two
// boxes as polyhedra on thousands of random pairs, and touching boxes overlap.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/obb.hpp"

using namespace recode::core;

namespace {

Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Obb randomBox(std::mt19937_64& rng, double spread) {
  std::uniform_real_distribution<double> size(0.05, 1.0), place(-spread, spread);
  Obb box;
  box.center = {place(rng), place(rng), place(rng)};
  box.axes = randomRotation(rng);
  box.halfExtents = {size(rng), size(rng), size(rng)};
  return box;
}

bool contains(const Obb& b, const Eigen::Vector3d& p, double tolerance = 0.0) {
  const Eigen::Vector3d local = b.axes.transpose() * (p - b.center);
  return (local.cwiseAbs().array() <= b.halfExtents.array() + tolerance).all();
}

// Does segment pq cross face `f` of box b (f = 2 * axis + side)? The face is the rectangle
// at local coordinate +-1 along `axis`.
bool segmentCrossesFace(const Obb& b, const Eigen::Vector3d& p, const Eigen::Vector3d& q, int axis,
                        int side) {
  const Eigen::Vector3d lp = b.axes.transpose() * (p - b.center);
  const Eigen::Vector3d lq = b.axes.transpose() * (q - b.center);
  const double plane = side ? b.halfExtents[axis] : -b.halfExtents[axis];
  const double dp = lp[axis] - plane, dq = lq[axis] - plane;
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq)
    return false;
  const double t = dp / (dp - dq);
  const Eigen::Vector3d x = lp + t * (lq - lp);
  for (int i = 0; i < 3; ++i)
    if (i != axis && std::abs(x[i]) > b.halfExtents[i])
      return false;
  return true;
}

// Two boxes (convex polyhedra) intersect iff a vertex of one lies in the other or an edge of
// one crosses a face of the other: the brute-force reference, independent of any axis test.
bool bruteForceIntersect(const Obb& a, const Obb& b) {
  for (int pass = 0; pass < 2; ++pass) {
    const Obb& x = pass ? b : a;
    const Obb& y = pass ? a : b;
    const auto corners = x.corners();
    for (const Eigen::Vector3d& c : corners)
      if (contains(y, c))
        return true;
    // Edges: corner pairs differing in one bit.
    for (int k = 0; k < 8; ++k)
      for (int bit = 0; bit < 3; ++bit) {
        const int m = k ^ (1 << bit);
        if (m < k)
          continue;
        for (int f = 0; f < 6; ++f)
          if (segmentCrossesFace(y, corners[static_cast<std::size_t>(k)],
                                 corners[static_cast<std::size_t>(m)], f / 2, f % 2))
            return true;
      }
  }
  return false;
}

}  // namespace

TEST_CASE("obb: SAT agrees with a brute-force polyhedron intersection test", "[obb]") {
  std::mt19937_64 rng(20240611);
  int overlapping = 0, apart = 0, skipped = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Obb a = randomBox(rng, 1.2), b = randomBox(rng, 1.2);
    const bool expected = bruteForceIntersect(a, b);
    // Pairs within a hair of touching are decided by rounding; the shrunk and grown copies
    // must agree for the pair to count.
    if (bruteForceIntersect(grown(a, -1e-7), grown(b, -1e-7)) != expected ||
        bruteForceIntersect(grown(a, 1e-7), grown(b, 1e-7)) != expected) {
      ++skipped;
      continue;
    }
    INFO("trial " << trial);
    REQUIRE(obbsOverlap(a, b) == expected);
    REQUIRE(obbsOverlap(b, a) == expected);
    (expected ? overlapping : apart)++;
  }
  // Both verdicts are well represented and hardly any pair was skipped.
  CHECK(overlapping > 3000);
  CHECK(apart > 3000);
  CHECK(skipped < 20);
}

TEST_CASE("obb: separated only across an edge-edge axis", "[obb]") {
  // Two unit cubes turned 45 degrees about different axes, edge toward edge: no face normal
  // separates them, only the cross product of the two edges.
  Obb a, b;
  a.halfExtents = b.halfExtents = Eigen::Vector3d::Constant(0.5);
  a.axes = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.axes = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  // a reaches furthest along y with its edge along z at (0, r); b reaches furthest along -y
  // with its edge along x at y = b.y - r. The edges cross (seen along y) 0.01 apart. Only
  // y = z x x separates them: every face normal sees the boxes' shadows overlap.
  const double r = std::sqrt(0.5);
  b.center = {0.2, 2 * r + 0.01, 0.0};
  CHECK_FALSE(obbsOverlap(a, b));
  CHECK_FALSE(bruteForceIntersect(a, b));
  b.center.y() = 2 * r - 0.01;
  CHECK(obbsOverlap(a, b));
  CHECK(bruteForceIntersect(a, b));
}

TEST_CASE("obb: touching boxes overlap, a hair apart they do not", "[obb]") {
  Obb a, b;
  a.halfExtents = {1, 1, 1};
  b.halfExtents = {0.5, 2, 0.25};
  b.center = {1.5, 0.3, -0.2};  // faces meet at x = 1
  CHECK(obbsOverlap(a, b));
  b.center.x() = 1.5 + 1e-6;
  CHECK_FALSE(obbsOverlap(a, b));
  // Corner to corner.
  b.center = {1.5, 3.0, 1.25};
  CHECK(obbsOverlap(a, b));
  b.center.z() += 1e-6;
  CHECK_FALSE(obbsOverlap(a, b));
}

TEST_CASE("obb: fitting contains every point and finds a turned box's axes", "[obb]") {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix3d rotation = randomRotation(rng);
    std::uniform_real_distribution<double> u(0.1, 3.0);
    const Eigen::Vector3d half(u(rng), u(rng), u(rng));
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = rotation;
    t.translation() = Eigen::Vector3d(u(rng), -u(rng), u(rng));
    const TriangleMesh box = transformed(makeBox(half), t);
    const Obb fit = fitObb(box.vertices);
    for (const Eigen::Vector3d& v : box.vertices)
      REQUIRE(contains(fit, v, 1e-12));
    // The covariance of a box's corners has the box's axes as eigenvectors: the fit is the
    // box itself (volume 8 * hx * hy * hz), never the looser axis-aligned box.
    CHECK(fit.volume() == Approx(8.0 * half.prod()).epsilon(1e-9));
    CHECK(std::abs(fit.axes.determinant() - 1.0) < 1e-12);
  }
  // A cone along z: the coordinate axes give the natural box.
  const TriangleMesh cone = makeCone(1.0, 3.0, 32);
  const Obb fit = fitObb(cone.vertices);
  CHECK(fit.volume() <= Approx(2.0 * 2.0 * 3.0));
  for (const Eigen::Vector3d& v : cone.vertices)
    CHECK(contains(fit, v, 1e-12));
}

TEST_CASE("obb: a moved box contains the moved points; its AABB contains its corners", "[obb]") {
  std::mt19937_64 rng(99);
  const TriangleMesh ellipsoid = makeEllipsoid(2.0, 0.5, 1.0, 12, 6);
  const Obb local = fitObb(ellipsoid.vertices);
  for (int trial = 0; trial < 100; ++trial) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = randomRotation(rng);
    t.translation() = Eigen::Vector3d(1, 2, 3) * trial * 0.1;
    const Obb moved = local.transformed(t);
    const Aabb box = moved.aabb();
    for (const Eigen::Vector3d& v : ellipsoid.vertices) {
      const Eigen::Vector3d w = t * v;
      REQUIRE(contains(moved, w, 1e-9));
      REQUIRE((w.array() >= box.min.array() - 1e-9).all());
      REQUIRE((w.array() <= box.max.array() + 1e-9).all());
    }
    for (const Eigen::Vector3d& c : moved.corners()) {
      REQUIRE((c.array() >= box.min.array() - 1e-12).all());
      REQUIRE((c.array() <= box.max.array() + 1e-12).all());
    }
  }
}

TEST_CASE("aabbsOverlap: closed intervals; empty boxes overlap nothing", "[obb]") {
  Aabb a, b;
  a.extend(Eigen::Vector3d(0, 0, 0));
  a.extend(Eigen::Vector3d(1, 1, 1));
  b.extend(Eigen::Vector3d(1, 0.5, 0.5));
  b.extend(Eigen::Vector3d(2, 2, 2));
  CHECK(aabbsOverlap(a, b));
  b.min.x() = std::nextafter(1.0, 2.0);
  CHECK_FALSE(aabbsOverlap(a, b));
  CHECK_FALSE(aabbsOverlap(a, Aabb{}));
  CHECK_FALSE(aabbsOverlap(Aabb{}, Aabb{}));
}
