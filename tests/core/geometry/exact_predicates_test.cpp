// orient3d at the edges of its double filter: a double determinant of the wrong sign whose
// permanent is dominated by one large difference, and a determinant below the smallest
// subnormal. tests/core/geometry/convex_hull_test.cpp checks it on random near-coplanar points
// against integer arithmetic.

#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

#include "recode/geometry/exact_predicates.hpp"

namespace recode::core {
namespace {

TEST_CASE("orient3d is exact where the double determinant has the wrong sign", "[predicates]") {
  // a and b lie in the plane z = 0 with d, c is 1024 above it: the determinant is
  // 1024 * ((a - d) x (b - d)).z, the 2-D orientation of a, b around d scaled by c.z - d.z, and
  // the permanent is 1024 * (|adx bdy| + |bdx ady|). d = (1/2 + i u, 1/2 + j u), u = 2^-53,
  // lies (j - i) u above the line y = x through a = (12, 12) and b = (24, 24); the exact 2-D
  // orientation is 12 (j - i) u > 0 (the terms in 11.5 * 23.5 and in u^2 cancel), but in
  // doubles (11.5 - 41 u)(23.5 - 48 u) - (23.5 - 41 u)(11.5 - 48 u) rounds to -2^-44 (the
  // classroom example of Kettner et al.). That wrong value is 2^-44 * 1024, below the filter's
  // bound of 7 u times the permanent (about 540 * 1024), so the exact path decides.
  const double u = std::ldexp(1.0, -53);
  const Eigen::Vector3d a(12, 12, 0), b(24, 24, 0), c(0, 0, 1024);
  for (const auto& [i, j] : {std::pair{41, 48}, std::pair{41, 55}, std::pair{42, 49}}) {
    const Eigen::Vector3d d(0.5 + i * u, 0.5 + j * u, 0);
    const double naive = (a.x() - d.x()) * (b.y() - d.y()) - (b.x() - d.x()) * (a.y() - d.y());
    REQUIRE(naive < 0);                // the double evaluation is wrong, as the example needs
    CHECK(orient3d(a, b, c, d) == 1);  // 1024 * 12 (j - i) u > 0
    CHECK(orient3d(b, a, c, d) == -1);
  }
}

TEST_CASE("orient3d keeps the sign of a determinant below the smallest subnormal", "[predicates]") {
  // Four points near 2^-342 whose products of three differences lie near 2^-1026, at the
  // bottom of the normal range. The exact determinant, evaluated in rational arithmetic (GMP),
  // is about 2.54e-324, half the smallest subnormal and positive. The double evaluation's
  // determinant is positive and above its bound, and gives that sign; the expansion arithmetic
  // would lose the two-products' errors below 2^-1074 here and find 0 (exact_predicates.cpp:
  // "barring underflow"), so a wider bound that sent this case to it would call the points
  // coplanar. (Below the normal range neither path is exact in general; this case pins that
  // the filter decides it.)
  const Eigen::Vector3d a(0x1.01f143p-342, 0x1.529b23p-342, -0x1.3783d6p-342);
  const Eigen::Vector3d b(-0x1.181048p-344, 0x1.4acc8p-343, -0x1.be2dd1p-343);
  const Eigen::Vector3d c(-0x1.8df969p-342, -0x1.f3a94p-348, -0x1.0d53f64p-343);
  const Eigen::Vector3d d(-0x1.d3fd798p-343, 0x1.3b2f36p-344, -0x1.65c0e57p-343);
  CHECK(orient3d(a, b, c, d) == 1);
}

}  // namespace
}  // namespace recode::core
