// Generators: every tessellation is a valid convex block with the documented counts,
// placement and volume.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/validate.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;

namespace {

constexpr double kPi = std::numbers::pi;

// Properties every generated solid must have. `inside` is a point in the solid's interior.
void checkClosedConvexSolid(const TriangleMesh& mesh, const Eigen::Vector3d& inside) {
  REQUIRE_NOTHROW(validateConvexBlock(mesh, "generated"));

  // Closed surface of genus 0.
  const auto v = static_cast<long long>(mesh.vertexCount());
  const auto e = static_cast<long long>(test::countEdges(mesh));
  const auto f = static_cast<long long>(mesh.triangleCount());
  CHECK(v - e + f == 2);
  CHECK(2 * e == 3 * f);

  // Shared vertices: no two vertices at the same position.
  std::vector<Eigen::Vector3d> sorted = mesh.vertices;
  std::sort(sorted.begin(), sorted.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    INFO("duplicate vertex at " << sorted[i].transpose());
    CHECK(sorted[i] != sorted[i - 1]);
  }

  // Outward, counter-clockwise faces: each normal points away from the interior point.
  std::size_t inward = 0;
  for (const Triangle& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (!(normal.dot((a + b + c) / 3.0 - inside) > 0.0)) {
      ++inward;
    }
  }
  CHECK(inward == 0);
  CHECK(signedVolume(mesh) > 0.0);
}

// Area of a regular polygon with `segments` sides and circumradius rho.
double polygonArea(double rho, int segments) {
  return 0.5 * segments * rho * rho * std::sin(2.0 * kPi / segments);
}

// Exact volume of a stack of frusta of regular polygons (aligned, similar) between the
// profile points (rho, z), scaled in x and y by sx, sy.
double stackVolume(const std::vector<std::pair<double, double>>& profile, int segments,
                   double sx = 1.0, double sy = 1.0) {
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const double a0 = sx * sy * polygonArea(profile[k].first, segments);
    const double a1 = sx * sy * polygonArea(profile[k + 1].first, segments);
    const double h = profile[k + 1].second - profile[k].second;
    volume += h / 3.0 * (a0 + a1 + std::sqrt(a0 * a1));
  }
  return volume;
}

// Profile of the capped cone as documented: bottom cap latitudes from -pi/2 to phi in
// `rings` equal steps, top cap from phi to pi/2 likewise.
std::vector<std::pair<double, double>> cappedConeProfile(double r0, double r1, double h,
                                                         int rings) {
  const double phi = std::asin((r0 - r1) / h);
  std::vector<std::pair<double, double>> profile{{0.0, -r0}};
  for (int k = 1; k <= rings; ++k) {
    const double psi = -kPi / 2 + (phi + kPi / 2) * k / rings;
    profile.emplace_back(r0 * std::cos(psi), r0 * std::sin(psi));
  }
  for (int k = 0; k < rings; ++k) {
    const double psi = phi + (kPi / 2 - phi) * k / rings;
    profile.emplace_back(r1 * std::cos(psi), h + r1 * std::sin(psi));
  }
  profile.emplace_back(0.0, h + r1);
  return profile;
}

// Volume of the convex hull of two spheres (radius r0 at the origin, r1 at height h):
// spherical cap below the lower tangent circle + frustum + spherical cap above the upper.
double cappedConeVolume(double r0, double r1, double h) {
  const double s = (r0 - r1) / h;  // sin(phi)
  const double c = std::sqrt(1.0 - s * s);
  const double h0 = r0 * (1.0 + s);
  const double h1 = r1 * (1.0 - s);
  const double bottom = kPi * h0 * h0 * (3.0 * r0 - h0) / 3.0;
  const double top = kPi * h1 * h1 * (3.0 * r1 - h1) / 3.0;
  const double length = h + (r1 - r0) * s;
  const double R0 = r0 * c;
  const double R1 = r1 * c;
  const double frustum = kPi * length / 3.0 * (R0 * R0 + R0 * R1 + R1 * R1);
  return bottom + frustum + top;
}

}  // namespace

TEST_CASE("cone: counts, placement, validity and volume", "[generators]") {
  const int segments = GENERATE(3, 4, 5, 8, 17, 64, 500);
  const double radius = 1.5;
  const double height = 2.5;
  CAPTURE(segments);
  const TriangleMesh mesh = makeCone(radius, height, segments);

  CHECK(mesh.vertexCount() == static_cast<std::size_t>(segments) + 2);
  CHECK(mesh.triangleCount() == 2 * static_cast<std::size_t>(segments));
  CHECK(mesh.vertices.front() == Eigen::Vector3d(0, 0, 0));      // base centre
  CHECK(mesh.vertices[1] == Eigen::Vector3d(radius, 0, 0));      // first rim vertex at +x
  CHECK(mesh.vertices.back() == Eigen::Vector3d(0, 0, height));  // apex
  for (int j = 0; j < segments; ++j) {
    const Eigen::Vector3d& p = mesh.vertices[1 + static_cast<std::size_t>(j)];
    CHECK(p.z() == 0.0);
    CHECK(p.head<2>().norm() == Approx(radius).epsilon(1e-14));
    CHECK(std::atan2(p.y(), p.x()) ==
          Approx(std::remainder(2 * kPi * j / segments, 2 * kPi)).margin(1e-12));
  }
  checkClosedConvexSolid(mesh, {0, 0, height / 4});

  // The tessellated cone is a pyramid over a regular polygon: exact volume A h / 3, which
  // lies between the cone inscribed in the polygon (radius r cos(pi/s)) and the true cone.
  const double exact = polygonArea(radius, segments) * height / 3.0;
  const double analytic = kPi * radius * radius * height / 3.0;
  const double volume = signedVolume(mesh);
  CHECK(volume == Approx(exact).epsilon(1e-12));
  CHECK(volume <= analytic);
  CHECK(volume >= analytic * std::pow(std::cos(kPi / segments), 2));
}

TEST_CASE("cylinder: counts, placement, validity and volume", "[generators]") {
  const int segments = GENERATE(3, 4, 7, 32, 257);
  const double radius = 0.75;
  const double height = 3.0;
  CAPTURE(segments);
  const TriangleMesh mesh = makeCylinder(radius, height, segments);

  CHECK(mesh.vertexCount() == 2 * static_cast<std::size_t>(segments) + 2);
  CHECK(mesh.triangleCount() == 4 * static_cast<std::size_t>(segments));
  CHECK(mesh.vertices.front() == Eigen::Vector3d(0, 0, 0));
  CHECK(mesh.vertices.back() == Eigen::Vector3d(0, 0, height));
  const Aabb box = boundingBox(mesh);
  CHECK(box.min.z() == 0.0);
  CHECK(box.max.z() == height);
  CHECK(box.max.x() == radius);
  checkClosedConvexSolid(mesh, {0, 0, height / 2});

  const double exact = polygonArea(radius, segments) * height;
  const double analytic = kPi * radius * radius * height;
  const double volume = signedVolume(mesh);
  CHECK(volume == Approx(exact).epsilon(1e-12));
  CHECK(volume <= analytic);
  CHECK(volume >= analytic * std::pow(std::cos(kPi / segments), 2));
}

TEST_CASE("ellipsoid and sphere: counts, placement, validity and volume", "[generators]") {
  const int segments = GENERATE(3, 4, 6, 13, 64);
  const int rings = GENERATE(2, 3, 4, 9, 32);
  const double a = 2.0;
  const double b = 1.0;
  const double c = 0.5;
  CAPTURE(segments, rings);
  const TriangleMesh mesh = makeEllipsoid(a, b, c, segments, rings);

  const auto s = static_cast<std::size_t>(segments);
  const auto r = static_cast<std::size_t>(rings);
  CHECK(mesh.vertexCount() == (r - 1) * s + 2);
  CHECK(mesh.triangleCount() == 2 * (r - 1) * s);
  CHECK(mesh.vertices.front() == Eigen::Vector3d(0, 0, -c));
  CHECK(mesh.vertices.back() == Eigen::Vector3d(0, 0, c));
  for (const Eigen::Vector3d& p : mesh.vertices) {
    const double level = std::pow(p.x() / a, 2) + std::pow(p.y() / b, 2) + std::pow(p.z() / c, 2);
    CHECK(level == Approx(1.0).epsilon(1e-14));
  }
  checkClosedConvexSolid(mesh, Eigen::Vector3d::Zero());

  // Exact volume of the tessellation: a stack of polygon frusta on the documented
  // latitudes psi_k = pi (2k - rings) / (2 rings).
  std::vector<std::pair<double, double>> profile{{0.0, -c}};
  for (int k = 1; k < rings; ++k) {
    const double psi = kPi * (2 * k - rings) / (2.0 * rings);
    profile.emplace_back(std::cos(psi), c * std::sin(psi));
  }
  profile.emplace_back(0.0, c);
  const double volume = signedVolume(mesh);
  CHECK(volume == Approx(stackVolume(profile, segments, a, b)).epsilon(1e-12));

  // Convergence: the tessellation is inscribed (volume <= analytic) and contains the
  // ellipsoid scaled by cos(pi / (2 rings)) (the meridian chords' distance from the centre)
  // along z and by cos(pi / (2 rings)) cos(pi / segments) across (polygon vs circle).
  const double analytic = 4.0 / 3.0 * kPi * a * b * c;
  const double lower =
      analytic * std::pow(std::cos(kPi / (2 * rings)), 3) * std::pow(std::cos(kPi / segments), 2);
  CHECK(volume <= analytic);
  CHECK(volume >= lower);
}

TEST_CASE("sphere is the ellipsoid with equal radii", "[generators]") {
  const TriangleMesh sphere = makeSphere(1.25, 12, 7);
  const TriangleMesh ellipsoid = makeEllipsoid(1.25, 1.25, 1.25, 12, 7);
  CHECK(sphere.vertices == ellipsoid.vertices);
  CHECK(sphere.triangles == ellipsoid.triangles);
  for (const Eigen::Vector3d& p : sphere.vertices) {
    CHECK(p.norm() == Approx(1.25).epsilon(1e-15));
  }
  // Even ring counts put a ring exactly on the equator.
  const TriangleMesh even = makeSphere(1.0, 8, 4);
  for (std::size_t j = 0; j < 8; ++j) {
    CHECK(even.vertices[1 + 8 + j].z() == 0.0);  // ring 1 (of rings 0..2)
  }
  // Converges toward 4/3 pi r^3.
  const double analytic = 4.0 / 3.0 * kPi;
  CHECK(signedVolume(makeSphere(1.0, 256, 128)) == Approx(analytic).epsilon(5e-4));
}

TEST_CASE("capped cone: counts, placement, validity and volume", "[generators]") {
  struct Shape {
    double r0, r1, height;
  };
  const Shape shape = GENERATE(Shape{1.0, 0.5, 3.0}, Shape{0.5, 1.0, 3.0}, Shape{1.0, 1.0, 2.0},
                               Shape{2.0, 0.25, 2.0}, Shape{0.3, 1.2, 1.0});
  const int segments = GENERATE(3, 5, 16, 64);
  const int rings = GENERATE(1, 2, 3, 8, 24);
  const double r0 = shape.r0;
  const double r1 = shape.r1;
  const double h = shape.height;
  CAPTURE(r0, r1, h, segments, rings);
  const TriangleMesh mesh = makeCappedCone(r0, r1, h, segments, rings);

  const auto s = static_cast<std::size_t>(segments);
  const auto r = static_cast<std::size_t>(rings);
  CHECK(mesh.vertexCount() == 2 * r * s + 2);
  CHECK(mesh.triangleCount() == 4 * r * s);
  CHECK(mesh.vertices.front() == Eigen::Vector3d(0, 0, -r0));
  CHECK(mesh.vertices.back() == Eigen::Vector3d(0, 0, h + r1));
  // Every vertex lies on one of the two spheres: the first half on the lower one.
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    const Eigen::Vector3d& p = mesh.vertices[i];
    if (i < mesh.vertexCount() / 2) {
      CHECK(p.norm() == Approx(r0).epsilon(1e-14));
    } else {
      CHECK((p - Eigen::Vector3d(0, 0, h)).norm() == Approx(r1).epsilon(1e-14));
    }
  }
  // The lateral band joins the two tangent circles, which correspond under the homothety
  // that maps the lower sphere onto the upper one; so each lateral face's plane is at
  // distances from the two centres in the ratio r0 : r1.
  const std::size_t lateralFirst = s + 2 * (r - 1) * s;  // after the bottom cap's triangles
  for (std::size_t t = lateralFirst; t < lateralFirst + 2 * s; ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d n =
        (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).normalized();
    const double d0 = n.dot(a);
    const double d1 = n.dot(a - Eigen::Vector3d(0, 0, h));
    CHECK(d0 * r1 == Approx(d1 * r0).epsilon(1e-12));
  }
  checkClosedConvexSolid(mesh, {0, 0, h / 2});

  const double volume = signedVolume(mesh);
  CHECK(volume ==
        Approx(stackVolume(cappedConeProfile(r0, r1, h, rings), segments)).epsilon(1e-12));

  // Convergence toward the analytic volume. Replacing each cap arc (angle delta, radius
  // rho) by its chord removes a circular segment of area rho^2 (delta - sin delta) / 2; by
  // Pappus its solid of revolution has volume at most 2 pi max(r0, r1) times that area.
  // The polygonal cross-sections then contain the discs scaled by cos(pi / segments).
  const double phi = std::asin((r0 - r1) / h);
  const double delta0 = (phi + kPi / 2) / rings;
  const double delta1 = (kPi / 2 - phi) / rings;
  const double segmentsArea =
      rings * (r0 * r0 * (delta0 - std::sin(delta0)) + r1 * r1 * (delta1 - std::sin(delta1))) / 2.0;
  const double analytic = cappedConeVolume(r0, r1, h);
  const double lower = (analytic - 2.0 * kPi * std::max(r0, r1) * segmentsArea) *
                       std::pow(std::cos(kPi / segments), 2);
  CHECK(volume <= analytic);
  CHECK(volume >= lower);
}

TEST_CASE("capped cone volume formula reduces to the capsule and converges", "[generators]") {
  // Equal radii: two hemispheres and a cylinder.
  CHECK(cappedConeVolume(1.0, 1.0, 2.0) == Approx(4.0 / 3.0 * kPi + 2.0 * kPi).epsilon(1e-14));
  // A fine tessellation approaches the analytic volume.
  const double analytic = cappedConeVolume(1.0, 0.4, 2.5);
  CHECK(signedVolume(makeCappedCone(1.0, 0.4, 2.5, 512, 128)) == Approx(analytic).epsilon(1e-4));
}

TEST_CASE("box: counts, placement, validity and volume", "[generators]") {
  const TriangleMesh mesh = makeBox(1.0, 2.0, 0.5);
  CHECK(mesh.vertexCount() == 8);
  CHECK(mesh.triangleCount() == 12);
  for (std::size_t i = 0; i < 8; ++i) {
    CHECK(mesh.vertices[i] == Eigen::Vector3d((i & 1) != 0 ? 1.0 : -1.0, (i & 2) != 0 ? 2.0 : -2.0,
                                              (i & 4) != 0 ? 0.5 : -0.5));
  }
  checkClosedConvexSolid(mesh, Eigen::Vector3d::Zero());
  CHECK(signedVolume(mesh) == Approx(8.0).epsilon(1e-15));
  const TriangleMesh same = makeBox(Eigen::Vector3d(1.0, 2.0, 0.5));
  CHECK(same.vertices == mesh.vertices);
  CHECK(same.triangles == mesh.triangles);
}

TEST_CASE("generators reject invalid parameters, naming parameter and value", "[generators]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::function<void()> call;
    std::vector<std::string> expected;  // substrings of the message
  };
  const std::vector<Case> cases = {
      {[] { (void)makeCone(-1.0, 1.0, 8); }, {"makeCone", "radius", "-1"}},
      {[] { (void)makeCone(1.0, 0.0, 8); }, {"makeCone", "height", "got 0"}},
      {[&] { (void)makeCone(nan, 1.0, 8); }, {"radius", "nan"}},
      {[] { (void)makeCone(1.0, 1.0, 2); }, {"segments must be at least 3, got 2"}},
      {[] { (void)makeCone(1.0, 1.0, -5); }, {"segments", "-5"}},
      {[] { (void)makeCone(1.0, 1.0, 20'000'000); }, {"segments = 20000000", "limit"}},
      {[&] { (void)makeCylinder(inf, 1.0, 8); }, {"makeCylinder", "radius", "inf"}},
      {[] { (void)makeCylinder(1.0, -2.5, 8); }, {"height", "-2.5"}},
      {[] { (void)makeCylinder(1.0, 1.0, 0); }, {"segments", "got 0"}},
      {[] { (void)makeCappedCone(0.0, 1.0, 2.0, 8, 2); }, {"makeCappedCone", "r0", "got 0"}},
      {[] { (void)makeCappedCone(1.0, -1.0, 2.0, 8, 2); }, {"r1", "-1"}},
      {[&] { (void)makeCappedCone(1.0, 1.0, nan, 8, 2); }, {"height", "nan"}},
      {[] { (void)makeCappedCone(1.0, 1.0, 2.0, 8, 0); }, {"rings must be at least 1, got 0"}},
      {[] { (void)makeCappedCone(1.0, 1.0, 2.0, 1, 2); }, {"segments", "got 1"}},
      {[] { (void)makeCappedCone(3.0, 1.0, 2.0, 8, 2); },
       {"height must exceed |r0 - r1| = 2", "got 2"}},
      {[] { (void)makeCappedCone(1.0, 1.5, 0.5, 8, 2); }, {"|r0 - r1| = 0.5", "got 0.5"}},
      {[] { (void)makeCappedCone(1.0, 1.0, 1.0, 100'000, 100'000); },
       {"segments = 100000 and rings = 100000", "limit"}},
      {[] { (void)makeEllipsoid(1.0, 0.0, 1.0, 8, 4); }, {"makeEllipsoid", "b", "got 0"}},
      {[] { (void)makeEllipsoid(1.0, 1.0, -3.0, 8, 4); }, {"c must be", "-3"}},
      {[&] { (void)makeEllipsoid(-inf, 1.0, 1.0, 8, 4); }, {"a must be", "-inf"}},
      {[] { (void)makeEllipsoid(1.0, 1.0, 1.0, 8, 1); }, {"rings must be at least 2, got 1"}},
      {[] { (void)makeSphere(-0.5, 8, 4); }, {"makeSphere", "radius", "-0.5"}},
      {[] { (void)makeSphere(1.0, 8, -1); }, {"rings", "-1"}},
      {[] { (void)makeSphere(1.0, 2, 4); }, {"segments", "got 2"}},
      {[] { (void)makeSphere(1.0, 10'000, 10'000); },
       {"makeSphere: segments = 10000 and rings = 10000", "limit of 33554432"}},
      {[] { (void)makeBox(1.0, 1.0, 0.0); }, {"makeBox", "hz", "got 0"}},
      {[&] { (void)makeBox(nan, 1.0, 1.0); }, {"hx", "nan"}},
      {[] { (void)makeBox(Eigen::Vector3d(1.0, -1.0, 1.0)); }, {"hy", "-1"}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    CAPTURE(i);
    std::string message;
    try {
      cases[i].call();
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    CAPTURE(message);
    REQUIRE_FALSE(message.empty());
    for (const std::string& part : cases[i].expected) {
      CHECK_THAT(message, Contains(part));
    }
  }
}
