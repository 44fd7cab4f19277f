// The exact predicates against integer arithmetic, and the convex hull on inputs whose hull is
// known by construction (a cube with points inside it, on its faces and edges, and repeated; a
// grid; a tetrahedron with near-coplanar points) and on the degenerate inputs it must refuse.
// tests/core/geometry/convex_hull_cgal_test.cpp compares it with CGAL on random sets.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/convex_hull.hpp"
#include "recode/geometry/exact_predicates.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core {
namespace {

using test::meshErrorMessage;

// Integer coordinates below 2^40, scaled by 2^-20 so they are exact doubles with fractions.
constexpr double kScale = 1.0 / (1 << 20);

using Int3 = std::array<std::int64_t, 3>;

Eigen::Vector3d toPoint(const Int3& q) {
  return {static_cast<double>(q[0]) * kScale, static_cast<double>(q[1]) * kScale,
          static_cast<double>(q[2]) * kScale};
}

// The sign of det[a - d; b - d; c - d] in 128-bit integers (differences < 2^41, products of
// three < 2^123): an oracle that shares no code or method with the expansion arithmetic.
int orient3dInteger(const Int3& a, const Int3& b, const Int3& c, const Int3& d) {
  __extension__ typedef __int128 I;  // GCC and Clang; -Wpedantic wants the marker
  const I adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const I bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const I cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const I det =
      adx * (bdy * cdz - bdz * cdy) - ady * (bdx * cdz - bdz * cdx) + adz * (bdx * cdy - bdy * cdx);
  return (det > 0) - (det < 0);
}

TEST_CASE("orient3d is exact on near-coplanar points", "[hull][predicates]") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 38),
                                                    std::int64_t{1} << 38);
  std::uniform_int_distribution<std::int64_t> small(-3, 3);
  std::uniform_int_distribution<std::int64_t> nudge(-1, 1);
  int doubleWrong = 0;
  int zeros = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Int3 a{coord(rng), coord(rng), coord(rng)};
    // b and c near a, d = a + s (b - a) + t (c - a) + a nudge of at most one unit: coplanar
    // or off the plane by the smallest step, where rounding decides the double determinant.
    const Int3 b{a[0] + coord(rng) / 1024, a[1] + coord(rng) / 1024, a[2] + coord(rng) / 1024};
    const Int3 c{a[0] + coord(rng) / 1024, a[1] + coord(rng) / 1024, a[2] + coord(rng) / 1024};
    const std::int64_t s = small(rng);
    const std::int64_t t = small(rng);
    Int3 d{};
    for (std::size_t k = 0; k < 3; ++k)
      d[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]) + nudge(rng);
    const int expected = orient3dInteger(a, b, c, d);
    const Eigen::Vector3d pa = toPoint(a), pb = toPoint(b), pc = toPoint(c), pd = toPoint(d);
    REQUIRE(orient3d(pa, pb, pc, pd) == expected);
    zeros += expected == 0 ? 1 : 0;
    const double naive = (pa - pd).dot((pb - pd).cross(pc - pd));
    doubleWrong += ((naive > 0) - (naive < 0)) != expected ? 1 : 0;
  }
  // The cases must be hard: plain double arithmetic gets many of them wrong.
  CHECK(zeros > 500);  // about 1 in 27: no nudge on any axis
  CHECK(doubleWrong > 100);
}

TEST_CASE("orient3d and orient2d signs follow the documented convention", "[hull][predicates]") {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  CHECK(orient3d(a, b, c, {0.2, 0.2, -1}) == 1);  // below the counter-clockwise triangle
  CHECK(orient3d(a, b, c, {0.2, 0.2, 1}) == -1);
  CHECK(orient3d(a, b, c, {5, -7, 0}) == 0);
  CHECK(orient2d(a, b, c, 0, 1) == 1);
  CHECK(orient2d(a, c, b, 0, 1) == -1);
  // 0.1 * 3 is not 0.3 in doubles: these three are not exactly collinear.
  CHECK_FALSE(collinear({0, 0, 0}, {0.1, 0.1, 0.1}, {0.3, 0.3, 0.1 * 3}));
  CHECK(collinear({0, 0, 0}, {0.25, 0.5, 1}, {0.75, 1.5, 3}));
  CHECK(collinear({1, 2, 3}, {1, 2, 3}, {4, 4, 4}));
}

void requireValidHull(const ConvexHull& hull, std::span<const Eigen::Vector3d> points) {
  REQUIRE(hull.inputIndex.size() == hull.mesh.vertices.size());
  for (std::size_t k = 0; k < hull.inputIndex.size(); ++k)
    REQUIRE(hull.mesh.vertices[k] == points[hull.inputIndex[k]]);
  const ValidationReport report = checkConvexBlock(hull.mesh);
  INFO((report.ok() ? std::string() : report.problems.front().message));
  REQUIRE(report.ok());
}

TEST_CASE("a tetrahedron's triangles are the starting simplex's faces in order", "[hull]") {
  // Four points: the hull is their tetrahedron, its triangles the incremental step's first four
  // faces in order: the simplex (a, b, c, d) less a, less b, less c, less d, each turned
  // outward. a = p0, the lowest (lexicographically smallest); b = p1, the farthest from it (10;
  // p2 is 5 away, p3 6); c the farthest from the line ab: |(b - a) x (q - a)| is 10 * 5 = 50
  // for p2 and 10 * 6 = 60 for p3, so c = p3 and d = p2. The faces, in the order of the point
  // each leaves out: {p1, p3, p2}, {p0, p3, p2}, {p0, p1, p2}, {p0, p1, p3}, each
  // counter-clockwise seen from outside (the left-out point behind it).
  const std::vector<Eigen::Vector3d> points{{0, 0, 10}, {10, 0, 10}, {0, 5, 10}, {0, 0, 16}};
  const ConvexHull hull = convexHull(points, "tetrahedron");
  requireValidHull(hull, points);
  CHECK(hull.mesh.triangles == std::vector<Triangle>{{1, 2, 3}, {0, 3, 2}, {0, 2, 1}, {0, 1, 3}});
}

TEST_CASE("a repeated lowest point is reported by its first index", "[hull]") {
  // p4 repeats p0, the lowest point, which starts the hull: the first of the two is taken (the
  // smallest element's first occurrence) and the copy, on the hull, is dropped.
  const std::vector<Eigen::Vector3d> points{
      {0, 0, 10}, {10, 0, 10}, {0, 5, 10}, {0, 0, 16}, {0, 0, 10}};
  const ConvexHull hull = convexHull(points, "tetrahedron");
  requireValidHull(hull, points);
  CHECK(hull.inputIndex == std::vector<std::size_t>{0, 1, 2, 3});
}

TEST_CASE("the hull of a cube keeps its 8 corners and drops points inside, on faces and edges",
          "[hull]") {
  std::vector<Eigen::Vector3d> points;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> inside(-0.99, 0.99);
  std::uniform_int_distribution<int> sign(0, 1);
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d q(inside(rng), inside(rng), inside(rng));
    const int kind = i % 4;  // 0 inside, 1 on a face, 2 on an edge, 3 a repeated corner
    if (kind >= 1)
      q[i % 3] = sign(rng) ? 1.0 : -1.0;
    if (kind >= 2)
      q[(i + 1) % 3] = sign(rng) ? 1.0 : -1.0;
    if (kind == 3)
      q[(i + 2) % 3] = sign(rng) ? 1.0 : -1.0;
    points.push_back(q);
  }
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  const ConvexHull hull = convexHull(points, "cube");
  requireValidHull(hull, points);
  REQUIRE(hull.mesh.vertexCount() == 8);
  CHECK(hull.mesh.triangleCount() == 12);  // each square face split in two
  for (const Eigen::Vector3d& v : hull.mesh.vertices)
    CHECK(v.cwiseAbs() == Eigen::Vector3d::Ones());
  CHECK(signedVolume(hull.mesh) == 8.0);
}

TEST_CASE("the hull of a grid is its 8 corners, however many points lie on its faces", "[hull]") {
  std::vector<Eigen::Vector3d> points;
  for (int x = 0; x <= 6; ++x)
    for (int y = 0; y <= 4; ++y)
      for (int z = 0; z <= 5; ++z)
        points.emplace_back(x, y, z);
  // Shuffled, so that the incremental step meets face points before the corners.
  std::shuffle(points.begin(), points.end(), std::mt19937(11));
  const ConvexHull hull = convexHull(points, "grid");
  requireValidHull(hull, points);
  CHECK(hull.mesh.vertexCount() == 8);
  CHECK(hull.mesh.triangleCount() == 12);
  CHECK(signedVolume(hull.mesh) == 6.0 * 4.0 * 5.0);
}

TEST_CASE("a planar face with points on its boundary keeps only its corners", "[hull]") {
  // A square pyramid whose base has points along its sides and inside it, and an apex.
  std::vector<Eigen::Vector3d> points{{0.5, 0.5, 3}};
  for (int i = 0; i <= 8; ++i) {
    const double t = i / 8.0;
    points.emplace_back(t, 0, 0);
    points.emplace_back(1, t, 0);
    points.emplace_back(1 - t, 1, 0);
    points.emplace_back(0, 1 - t, 0);
    points.emplace_back(t, 1 - t, 0);  // the base's diagonal
  }
  const ConvexHull hull = convexHull(points, "pyramid");
  requireValidHull(hull, points);
  CHECK(hull.mesh.vertexCount() == 5);
  CHECK(hull.mesh.triangleCount() == 6);
  CHECK(signedVolume(hull.mesh) == Approx(1.0).epsilon(1e-14));  // base 1, height 3: 1/3 * 3
}

TEST_CASE("the hull is exact; a block also needs its triangles above the tolerance", "[hull]") {
  // A prism, a point one unit in the last place above the middle of its top face (a corner of
  // the exact hull; its nearly flat triangles make a valid block), and a second corner 1e-12
  // from (2, 0, 0) (also a corner, but its edge to (2, 0, 0) is far below the tolerance).
  std::vector<Eigen::Vector3d> points{{0, 0, 0}, {2, 0, 0}, {0, 2, 0},
                                      {0, 0, 1}, {2, 0, 1}, {0, 2, 1}};
  const Eigen::Vector3d raised(0.5, 0.5, std::nextafter(1.0, 2.0));
  points.push_back(raised);
  const ConvexHull hull = convexHull(points, "prism");
  requireValidHull(hull, points);
  CHECK(hull.mesh.vertexCount() == 7);
  CHECK(std::find(hull.mesh.vertices.begin(), hull.mesh.vertices.end(), raised) !=
        hull.mesh.vertices.end());
  CHECK(convexHullBlock(points, "prism").vertexCount() == 7);

  const Eigen::Vector3d near(2 - 1e-12, -1e-12, 0);
  points.push_back(near);
  const ConvexHull exact = convexHull(points, "prism");
  CHECK(exact.mesh.vertexCount() == 8);
  CHECK_FALSE(checkConvexBlock(exact.mesh).ok());  // a triangle 1e-12 thin
  // The block drops one of the two close corners, and only that.
  const TriangleMesh block = convexHullBlock(points, "prism");
  CHECK(checkConvexBlock(block).ok());
  CHECK(block.vertexCount() == 7);
  const auto has = [&](const Eigen::Vector3d& q) {
    return std::find(block.vertices.begin(), block.vertices.end(), q) != block.vertices.end();
  };
  CHECK(has(raised));
  CHECK(has(near) != has(Eigen::Vector3d(2, 0, 0)));
}

TEST_CASE("a hull too thin for the tolerance is refused with the rule", "[hull]") {
  // A unit square slab 1e-12 thick: exact, it spans a volume; as a block it cannot.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1, (i >> 1) & 1, (i & 4) ? 1e-12 : 0.0);
  CHECK(convexHull(points, "slab.obj").mesh.vertexCount() == 8);
  const std::string message = meshErrorMessage([&] { (void)convexHullBlock(points, "slab.obj"); });
  // Dropping the corners of the thin side triangles leaves points that span no volume:
  // convexHull's own problem follows, its "slab.obj: " cut off (the prefix names the source).
  CHECK_THAT(message, Catch::StartsWith("slab.obj: the convex hull of its 8 points is not a "
                                        "valid convex block (convex hull: "));
  CHECK_THAT(message, Catch::EndsWith("); its points are too close to one plane, line or point "
                                      "for the validation tolerance"));
}

TEST_CASE("degenerate point sets are refused with the rule", "[hull]") {
  const auto message = [](std::vector<Eigen::Vector3d> points) {
    return meshErrorMessage([&] { (void)convexHull(points, "plate.obj"); });
  };
  const std::string rule = "(a convex hull needs at least 4 points that do not lie in one plane)";
  CHECK(message({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) ==
        "plate.obj: convex hull: only 3 points " + rule);
  CHECK(message({}) == "plate.obj: convex hull: only 0 points " + rule);
  CHECK(message({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}) ==
        "plate.obj: convex hull: all 5 points are the same point (1, 2, 3) " + rule);
  CHECK(message({{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {0.5, 0.5, 0.5}, {-3, -3, -3}}) ==
        "plate.obj: convex hull: all 5 points lie on one line " + rule);
  std::vector<Eigen::Vector3d> flat;
  for (int i = 0; i < 30; ++i)
    flat.emplace_back(i % 6, i / 6, 0.25 * (i % 6) + 0.5 * (i / 6));  // the plane z = x/4 + y/2
  CHECK(message(flat) == "plate.obj: convex hull: all 30 points lie in one plane " + rule);
  flat.back().z() = std::nextafter(flat.back().z(), 10.0);  // off the plane by one ulp
  CHECK(convexHull(flat, "plate.obj").mesh.vertexCount() >= 4);
  CHECK(message({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}}) ==
        "plate.obj: convex hull: point 3 (0, 0, nan) has a non-finite coordinate");
}

}  // namespace
}  // namespace recode::core
