// GJK distance between convex hulls: boxes a known gap apart (turned and moved together, which
// keeps the gap), a point and a box, overlapping and touching blocks, and many random pairs of
// boxes checked against the per-axis gap formula.

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/convex_distance.hpp"
#include "recode/geometry/generators.hpp"

using namespace recode::core;

namespace {

std::vector<Eigen::Vector3d> boxPoints(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                       const Eigen::Isometry3d& t) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 8; ++k)
    out.push_back(t * Eigen::Vector3d(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(),
                                      k & 4 ? hi.z() : lo.z()));
  return out;
}

// Distance between two axis-aligned boxes: the norm of the per-axis gaps.
double boxGap(const Eigen::Vector3d& lo1, const Eigen::Vector3d& hi1, const Eigen::Vector3d& lo2,
              const Eigen::Vector3d& hi2) {
  Eigen::Vector3d gap;
  for (int i = 0; i < 3; ++i)
    gap[i] = std::max({0.0, lo2[i] - hi1[i], lo1[i] - hi2[i]});
  return gap.norm();
}

}  // namespace

TEST_CASE("convexHullDistance: random box pairs, turned together, keep their gap", "[gjk]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> place(-2.0, 2.0), size(0.1, 1.5);
  std::normal_distribution<double> n(0.0, 1.0);
  int apart = 0, overlapping = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Eigen::Vector3d lo1(place(rng), place(rng), place(rng)),
        lo2(place(rng), place(rng), place(rng));
    const Eigen::Vector3d hi1 = lo1 + Eigen::Vector3d(size(rng), size(rng), size(rng));
    const Eigen::Vector3d hi2 = lo2 + Eigen::Vector3d(size(rng), size(rng), size(rng));
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
    t.translation() = Eigen::Vector3d(place(rng), place(rng), place(rng));
    const double expected = boxGap(lo1, hi1, lo2, hi2);
    const auto a = boxPoints(lo1, hi1, t), b = boxPoints(lo2, hi2, t);
    const double d = convexHullDistance(a, b);
    const double gap = convexHullGap(a, b);
    INFO("trial " << trial);
    if (expected > 0.0) {
      REQUIRE(d == Approx(expected).margin(1e-9));
      // The certified gap is a lower bound, and GJK's direction makes it tight.
      REQUIRE(gap <= expected + 1e-12);
      REQUIRE(gap == Approx(expected).margin(1e-9));
      ++apart;
    } else {
      REQUIRE(d == 0.0);
      REQUIRE(gap == 0.0);
      ++overlapping;
    }
  }
  CHECK(apart > 1000);
  CHECK(overlapping > 100);
}

TEST_CASE("convexHullGap: a gap far below any pixel is certified; a touch is not", "[gjk]") {
  // Two unit cubes face to face along x, 1e-7 apart, turned together: the gap survives.
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond(0.9, 0.2, -0.3, 0.1).normalized().toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.4, -1.2, 2.5);
  const Eigen::Vector3d lo(0, 0, 0), hi(1, 1, 1), shift(1.0 + 1e-7, 0.2, -0.1);
  const auto a = boxPoints(lo, hi, t);
  // A lower bound: GJK can stop on a face-to-face pair with its direction a few nanoradians
  // off the face normal, which tilts the slab (here by about 3 %).
  const double gap = convexHullGap(a, boxPoints(lo + shift, hi + shift, t));
  CHECK(gap <= 1e-7 + 1e-13);
  CHECK(gap > 0.9e-7);
  // Touching exactly (before rounding) and overlapping by 1e-7: no gap above rounding, so no
  // gap at all.
  const Eigen::Vector3d touch(1.0, 0.2, -0.1), overlap(1.0 - 1e-7, 0.2, -0.1);
  CHECK(convexHullGap(a, boxPoints(lo + touch, hi + touch, t)) == 0.0);
  CHECK(convexHullGap(a, boxPoints(lo + overlap, hi + overlap, t)) == 0.0);
  CHECK_THROWS_AS(convexHullGap(a, std::vector<Eigen::Vector3d>{}), std::invalid_argument);
}

TEST_CASE("convexHullDistance: points, touching and overlapping blocks", "[gjk]") {
  const std::vector<Eigen::Vector3d> point = {{3.0, 4.0, 0.5}};
  const TriangleMesh cube = makeBox(0.5, 0.5, 0.5);
  // From (3, 4, 0.5) to the cube [-0.5, 0.5]^3: gaps 2.5, 3.5, 0.
  CHECK(convexHullDistance(point, cube.vertices) == Approx(std::hypot(2.5, 3.5)));
  CHECK(convexHullDistance(cube.vertices, point) == Approx(std::hypot(2.5, 3.5)));
  // A cone's apex resting exactly on the cube's top face, then 1e-6 above it.
  TriangleMesh cone = makeCone(0.3, 1.0, 24);
  for (Eigen::Vector3d& v : cone.vertices)
    v = Eigen::Vector3d(v.x(), v.y(), 1.5 - v.z());  // apex down at z = 0.5
  CHECK(convexHullDistance(cone.vertices, cube.vertices) == 0.0);
  for (Eigen::Vector3d& v : cone.vertices)
    v.z() += 1e-6;
  CHECK(convexHullDistance(cone.vertices, cube.vertices) == Approx(1e-6).margin(1e-12));
  // A sphere of radius 1 around a small box: inside, so 0.
  const TriangleMesh ball = makeSphere(1.0, 12, 6);
  CHECK(convexHullDistance(ball.vertices, makeBox(0.1, 0.1, 0.1).vertices) == 0.0);
  CHECK_THROWS_AS(convexHullDistance(std::vector<Eigen::Vector3d>{}, cube.vertices),
                  std::invalid_argument);
}

TEST_CASE("hullsApartBeyond: apart by more than the margin's reach along the gap, and no less",
          "[gjk]") {
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const std::vector<Eigen::Vector3d> a = boxPoints({0, 0, 0}, {1, 1, 1}, identity);
  const Eigen::Vector3d margin(0.01, 0.02, 0.03);
  // B above A along z by g: the grown A reaches margin.z towards it, whatever x and y give.
  for (const double g : {0.0299, 0.0301}) {
    const std::vector<Eigen::Vector3d> b = boxPoints({0.2, 0.3, 1 + g}, {0.8, 0.9, 2}, identity);
    INFO("gap " << g);
    CHECK(hullsApartBeyond(a, b, margin) == (g > margin.z()));
    CHECK(hullsApartBeyond(b, a, margin) == (g > margin.z()));  // the margin grows b now
  }
  // B off A's edge along the diagonal (1, 1, 0). Across the diagonal the gap, sqrt(2) g, is
  // less than the box's reach, (margin.x + margin.y) / sqrt(2), for g under 0.015; along x the
  // gap is g against margin.x. The slab must be sought between the grown hull and B (GJK's
  // closest direction turns to x), not across the bare hulls' closest direction.
  for (const double g : {0.0099, 0.0101}) {
    const std::vector<Eigen::Vector3d> b = boxPoints({1 + g, 1 + g, 0}, {2, 2, 1}, identity);
    INFO("diagonal gap " << g);
    CHECK(hullsApartBeyond(a, b, margin) == (g > margin.x()));
  }
  CHECK_FALSE(hullsApartBeyond(a, a, Eigen::Vector3d::Zero()));
  CHECK_THROWS_AS(hullsApartBeyond(a, a, Eigen::Vector3d(-1, 0, 0)), std::invalid_argument);
  CHECK_THROWS_AS(hullsApartBeyond({}, a, margin), std::invalid_argument);
}

TEST_CASE("hullsApartBeyond: large sets, proven from a sample's direction or from all points",
          "[gjk]") {
  // Two tessellated balls, their poles facing along z: the gap between the pole vertices is the
  // hulls' gap. Well apart, GJK's direction from a sample of 64 points a side proves it; a hair
  // past the margin, only the direction from all points does (the slab along a sample's direction,
  // a little off the poles' line, is narrower than the gap by more than the hair).
  const TriangleMesh ball = makeSphere(1.0, 96, 48);
  REQUIRE(ball.vertices.size() > 2000);
  double top = -1e300, bottom = 1e300;
  for (const Eigen::Vector3d& p : ball.vertices) {
    top = std::max(top, p.z());
    bottom = std::min(bottom, p.z());
  }
  const Eigen::Vector3d margin(0.01, 0.01, 0.01);
  for (const double factor : {3.0, 1.001, 0.999}) {
    const double gap = factor * margin.z();
    std::vector<Eigen::Vector3d> b = ball.vertices;
    for (Eigen::Vector3d& p : b)
      p.z() += top - bottom + gap;
    INFO("gap " << factor << " margins");
    CHECK(hullsApartBeyond(ball.vertices, b, margin) == (factor > 1.0));
  }
}

TEST_CASE("hullsApartBeyond of posed sets: the thresholds of the world sets, read locally",
          "[gjk]") {
  // The diagonal case above, each box given in its own coordinates under a pose that turns it a
  // quarter about z (an exact matrix) and moves it: the world points are the boxes above.
  Eigen::Isometry3d quarter = Eigen::Isometry3d::Identity();
  quarter.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d margin(0.01, 0.02, 0.03);
  const auto posed = [&](const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    Eigen::Isometry3d pose = quarter;
    pose.translation() = Eigen::Vector3d(5.0, -3.0, 2.0);
    // Local points whose images under `pose` are the box [lo, hi].
    std::vector<Eigen::Vector3d> local = boxPoints(lo, hi, identity);
    for (Eigen::Vector3d& p : local)
      p = quarter.linear().transpose() * (p - pose.translation());
    return std::make_pair(local, pose);
  };
  const auto [a, poseA] = posed({0, 0, 0}, {1, 1, 1});
  for (const double g : {0.0099, 0.0101}) {
    const auto [b, poseB] = posed({1 + g, 1 + g, 0}, {2, 2, 1});
    INFO("diagonal gap " << g);
    CHECK(hullsApartBeyond(PosedPoints{a, poseA}, PosedPoints{b, poseB}, margin) ==
          (g > margin.x()));
  }
  for (const double g : {0.0299, 0.0301}) {
    const auto [b, poseB] = posed({0.2, 0.3, 1 + g}, {0.8, 0.9, 2});
    INFO("gap " << g);
    CHECK(hullsApartBeyond(PosedPoints{a, poseA}, PosedPoints{b, poseB}, margin) ==
          (g > margin.z()));
  }
  CHECK_THROWS_AS(hullsApartBeyond(PosedPoints{{}, poseA}, PosedPoints{a, poseA}, margin),
                  std::invalid_argument);
}

TEST_CASE("hullsApartBeyond of posed sets agrees with the world sets on turned balls", "[gjk]") {
  // Two tessellated balls under random turns, far from the origin, a gap between their centres'
  // spheres from well clear to overlapping: the answer from local points and poses must be the
  // answer from the world points (core::transformed's arithmetic), and true only where the
  // balls' hulls (inside spheres of radius 1) can be apart by more than the margin's reach.
  const TriangleMesh ball = makeSphere(1.0, 48, 24);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159), unit(-1.0, 1.0);
  const Eigen::Vector3d margin(0.004, 0.006, 0.005);
  int proven = 0, cases = 0;
  for (int k = 0; k < 60; ++k) {
    const auto randomPose = [&](const Eigen::Vector3d& at) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.rotate(Eigen::AngleAxisd(angle(rng),
                                    Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized()));
      pose.pretranslate(at);
      return pose;
    };
    const Eigen::Vector3d centre(1e4 + unit(rng), -2e4 + unit(rng), 3e3);
    const Eigen::Vector3d direction = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const double gap = std::vector<double>{0.5, 0.05, 0.02, 0.0, -0.1}[k % 5];
    const Eigen::Isometry3d poseA = randomPose(centre);
    const Eigen::Isometry3d poseB = randomPose(centre + (2.0 + gap) * direction);
    const TriangleMesh worldA = transformed(ball, poseA), worldB = transformed(ball, poseB);
    const bool local = hullsApartBeyond(PosedPoints{ball.vertices, poseA},
                                        PosedPoints{ball.vertices, poseB}, margin);
    INFO("case " << k << ", gap " << gap);
    CHECK(local == hullsApartBeyond(worldA.vertices, worldB.vertices, margin));
    if (gap < 0.0)
      CHECK_FALSE(local);  // a hull's faces sag at most 1 - cos(pi / 24) < 0.01 inside its sphere
    if (gap >= 0.5)
      CHECK(local);
    proven += local ? 1 : 0;
    ++cases;
  }
  CHECK(proven >= cases / 5);
}
