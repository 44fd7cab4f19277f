// validateConvexBlock / checkConvexBlock: each rule rejects what it should, with a message
// naming the problem, and accepts valid convex blocks.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/validate.hpp"
#include "test_shapes.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using recode::core::test::makeTorus;
using recode::core::test::meshErrorMessage;

namespace {

std::string validationMessage(const TriangleMesh& mesh, const char* name = "block",
                              double relativeTolerance = 1e-9) {
  return meshErrorMessage([&] { validateConvexBlock(mesh, name, relativeTolerance); });
}

// Independent brute force: for the first triangle (in index order) that some vertex lies
// more than tol in front of, that triangle and its farthest such vertex (lowest index on
// ties). Returns false if there is none.
struct Violation {
  std::size_t triangle = 0;
  std::size_t vertex = 0;
  double distance = 0.0;
};
bool firstConvexityViolation(const TriangleMesh& mesh, double relativeTolerance, Violation& out) {
  const double tol = relativeTolerance * boundingBox(mesh).diagonal();
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const double offset = n.dot((a + b + c) / 3.0);
    bool found = false;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
      const double d = n.dot(mesh.vertices[v]) - offset;
      if (d > tol && (!found || d > out.distance)) {
        out = {t, v, d};
        found = true;
      }
    }
    if (found) {
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("valid convex blocks pass", "[validate]") {
  CHECK_NOTHROW(validateConvexBlock(makeBox(1.0, 2.0, 3.0), "box"));
  CHECK_NOTHROW(validateConvexBlock(makeSphere(1.0, 64, 32), "sphere"));
  CHECK_NOTHROW(validateConvexBlock(makeCappedCone(1.0, 0.2, 4.0, 48, 12), "capped cone"));
  // A large tessellation (over 250k triangles) is checked too.
  const TriangleMesh fine = makeEllipsoid(3.0, 2.0, 1.0, 512, 256);
  REQUIRE(fine.triangleCount() > 250'000);
  const ValidationReport report = checkConvexBlock(fine);
  CHECK(report.ok());
  CHECK_FALSE(report.truncated);
}

TEST_CASE("no triangles", "[validate]") {
  CHECK(validationMessage(TriangleMesh{}, "empty") == "empty: the mesh has no triangles");
  TriangleMesh onlyVertices;
  onlyVertices.vertices = makeBox(1, 1, 1).vertices;
  const ValidationReport report = checkConvexBlock(onlyVertices);
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].kind == MeshProblemKind::NoTriangles);
}

TEST_CASE("non-finite coordinates name the vertex", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK(validationMessage(mesh, "nan-box") ==
        "nan-box: vertex 3 has a non-finite coordinate (nan, 1, -1)");
  mesh.vertices[6].z() = -std::numeric_limits<double>::infinity();
  const ValidationReport report = checkConvexBlock(mesh);
  REQUIRE(report.problems.size() == 2);
  CHECK(report.problems[1].kind == MeshProblemKind::NonFiniteCoordinate);
  CHECK(report.problems[1].message == "vertex 6 has a non-finite coordinate (-1, 1, -inf)");
}

TEST_CASE("index out of range", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.triangles[5][2] = 12;
  CHECK(validationMessage(mesh) ==
        "block: triangle 5 has vertex index 12 out of range (8 vertices)");
}

TEST_CASE("degenerate triangles: repeated index and zero area", "[validate]") {
  TriangleMesh repeated = makeBox(1.0, 1.0, 1.0);
  repeated.triangles[2] = {1, 3, 1};
  CHECK(validationMessage(repeated) ==
        "block: triangle 2 (vertices 1, 3, 1) repeats vertex index 1");

  // A flat triangle: three collinear points plus an apex, closed as a degenerate tetrahedron.
  TriangleMesh sliver;
  sliver.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}};
  sliver.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const std::string message = validationMessage(sliver);
  CHECK_THAT(message, StartsWith("block: triangle 0 (vertices 0, 2, 1) has zero area: its "
                                 "height over its longest edge is 0 (tolerance "));
}

TEST_CASE("unused vertex", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.vertices.emplace_back(0.0, 0.0, 0.0);
  CHECK(validationMessage(mesh) == "block: vertex 8 (0, 0, 0) is not used by any triangle");
}

TEST_CASE("open mesh: a box with one side removed", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.triangles.resize(10);  // drop the two +z triangles {4, 5, 7}, {4, 7, 6}
  CHECK(validationMessage(mesh, "open-box") ==
        "open-box: edge (4, 5) is used by only one triangle (triangle 5): the mesh is not "
        "closed");
  const ValidationReport report = checkConvexBlock(mesh);
  REQUIRE(report.problems.size() == 4);  // the rim 4-5, 4-6, 5-7, 6-7
  for (const MeshProblem& p : report.problems) {
    CHECK(p.kind == MeshProblemKind::OpenEdge);
  }
  CHECK_THAT(report.problems[3].message, StartsWith("edge (6, 7) is used by only one"));
}

TEST_CASE("flipped face: inconsistent orientation", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);  // {0, 4, 6} -> {0, 6, 4}
  CHECK(validationMessage(mesh, "flipped") ==
        "flipped: edge (0, 4) is used twice in the same direction (triangles 0 and 5): "
        "inconsistent orientation");
  const ValidationReport report = checkConvexBlock(mesh);
  CHECK(report.problems.size() == 3);  // the three edges of the flipped triangle
  for (const MeshProblem& p : report.problems) {
    CHECK(p.kind == MeshProblemKind::InconsistentOrientation);
  }
}

TEST_CASE("edge shared by more than two triangles", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.vertices.emplace_back(0.0, 0.0, 3.0);
  mesh.triangles.push_back({4, 5, 8});
  mesh.triangles.push_back({5, 4, 8});
  CHECK(validationMessage(mesh) ==
        "block: edge (4, 5) is used by 4 triangles (triangles 5, 10, 12, 13); a closed surface "
        "uses it twice");
}

TEST_CASE("two components and a torus are not single genus-0 surfaces", "[validate]") {
  TriangleMesh two = makeBox(1.0, 1.0, 1.0);
  const TriangleMesh other = makeBox(0.5, 0.5, 0.5);
  for (const Eigen::Vector3d& p : other.vertices) {
    two.vertices.push_back(p + Eigen::Vector3d(5.0, 0.0, 0.0));
  }
  for (const Triangle& t : other.triangles) {
    two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  }
  CHECK(validationMessage(two, "two") ==
        "two: the mesh has 2 connected components; a convex block is one closed surface");

  const TriangleMesh torus = makeTorus(12, 8);
  CHECK(validationMessage(torus, "torus") ==
        "torus: Euler characteristic V - E + F = 96 - 288 + 192 = 0, expected 2 (a closed "
        "surface without handles)");
}

TEST_CASE("inward orientation", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 2.0, 3.0);
  for (Triangle& t : mesh.triangles) {
    std::swap(t[1], t[2]);
  }
  CHECK(validationMessage(mesh, "inward") ==
        "inward: signed volume is -48 (must be > 0): the faces point inward");
  const ValidationReport report = checkConvexBlock(mesh);
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].kind == MeshProblemKind::InwardOrientation);
}

TEST_CASE("non-convex: a box with one corner pushed in", "[validate]") {
  TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
  mesh.vertices[7] = Eigen::Vector3d(0.5, 0.5, 0.5);
  Violation expected;
  REQUIRE(firstConvexityViolation(mesh, 1e-9, expected));
  const std::string message = validationMessage(mesh, "dented");
  CAPTURE(message);
  CHECK_THAT(message, StartsWith("dented: vertex " + std::to_string(expected.vertex) + " "));
  CHECK_THAT(message, Contains("outside the plane of triangle " +
                               std::to_string(expected.triangle) + " (vertices "));
  CHECK_THAT(message, Contains("the mesh is not convex"));
  // The reported distance is the brute-force one.
  const std::string lies = " lies ";
  const std::size_t at = message.find(lies);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(message.substr(at + lies.size())) == Approx(expected.distance).epsilon(1e-12));
  // Every face touching the dent's neighbourhood is reported up to the limit.
  const ValidationReport report = checkConvexBlock(mesh, 1e-9, 100);
  CHECK_FALSE(report.truncated);
  CHECK(report.problems.size() >= 3);
  for (const MeshProblem& p : report.problems) {
    CHECK(p.kind == MeshProblemKind::NotConvex);
  }
}

TEST_CASE("convexity tolerance is relative to the bounding-box diagonal", "[validate]") {
  // Pushing corner 7 of the box [-1, 1]^3 down by delta puts corner 6 about delta in
  // front of the plane of triangle 10 {4, 5, 7}. The diagonal is 2 sqrt(3), so with a
  // relative tolerance of 1e-6 the absolute tolerance is 3.46e-6.
  auto dented = [](double delta) {
    TriangleMesh mesh = makeBox(1.0, 1.0, 1.0);
    mesh.vertices[7].z() -= delta;
    return mesh;
  };
  CHECK_NOTHROW(validateConvexBlock(dented(1e-6), "small dent", 1e-6));
  const std::string message = validationMessage(dented(1e-5), "dent", 1e-6);
  CHECK_THAT(message, StartsWith("dent: vertex 6 (-1, 1, 1) lies 9.99"));
  CHECK_THAT(message, Contains("outside the plane of triangle 10 (vertices 4, 5, 7) "
                               "(tolerance 3.464"));
  // The same dent scaled up 1000 times is still within the (scaled) tolerance.
  TriangleMesh big = dented(1e-6);
  for (Eigen::Vector3d& p : big.vertices) {
    p *= 1000.0;
  }
  CHECK_NOTHROW(validateConvexBlock(big, "big", 1e-6));
  CHECK_THROWS_AS(checkConvexBlock(big, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(checkConvexBlock(big, std::numeric_limits<double>::quiet_NaN()),
                  std::invalid_argument);
  CHECK_THROWS_AS(checkConvexBlock(big, 1e-9, 0), std::invalid_argument);
}

TEST_CASE("convexity search agrees with brute force on perturbed spheres", "[validate]") {
  const TriangleMesh sphere = makeSphere(1.0, 40, 20);
  std::mt19937 random(20240611);
  std::uniform_int_distribution<std::size_t> pick(0, sphere.vertexCount() - 1);
  std::uniform_real_distribution<double> scale(0.9, 1.1);
  int violations = 0;
  for (int trial = 0; trial < 40; ++trial) {
    TriangleMesh mesh = sphere;
    for (int k = 0; k < 1 + trial % 3; ++k) {
      mesh.vertices[pick(random)] *= scale(random);
    }
    CAPTURE(trial);
    Violation expected;
    const bool violated = firstConvexityViolation(mesh, 1e-9, expected);
    const ValidationReport report = checkConvexBlock(mesh, 1e-9, 1);
    if (!violated) {
      CHECK(report.ok());
      continue;
    }
    ++violations;
    REQUIRE(report.problems.size() == 1);
    CHECK(report.problems[0].kind == MeshProblemKind::NotConvex);
    CHECK_THAT(report.problems[0].message,
               StartsWith("vertex " + std::to_string(expected.vertex) + " "));
    CHECK_THAT(report.problems[0].message,
               Contains("the plane of triangle " + std::to_string(expected.triangle) + " "));
  }
  // Pushing a vertex in or out by up to 10% breaks convexity almost always.
  CHECK(violations >= 30);
}

TEST_CASE("a surface wound twice around a convex solid", "[validate]") {
  // An octahedron whose equator is traversed twice: ring vertices 4..7 repeat the
  // positions of 0..3, and the upper and lower fans go around twice. Every edge is used
  // once in each direction, V - E + F = 10 - 24 + 16 = 2, all faces lie on the
  // octahedron's faces, but each point of the solid is enclosed twice.
  TriangleMesh mesh;
  const Eigen::Vector3d ring[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.push_back(ring[k % 4]);
  }
  mesh.vertices.emplace_back(0, 0, 1);   // 8
  mesh.vertices.emplace_back(0, 0, -1);  // 9
  for (VertexIndex k = 0; k < 8; ++k) {
    const VertexIndex next = (k + 1) % 8;
    mesh.triangles.push_back({k, next, 8});
    mesh.triangles.push_back({next, k, 9});
  }
  const ValidationReport report = checkConvexBlock(mesh);
  REQUIRE(report.problems.size() == 1);
  CHECK(report.problems[0].kind == MeshProblemKind::MultipleWinding);
  CHECK_THAT(validationMessage(mesh, "double"),
             StartsWith("double: the surface winds 2 times around its interior") &&
                 Contains("a convex block's surface winds once"));
}

TEST_CASE("report limits and problem names", "[validate]") {
  TriangleMesh mesh = makeSphere(1.0, 16, 8);
  for (Eigen::Vector3d& p : mesh.vertices) {
    p.x() = std::numeric_limits<double>::quiet_NaN();
  }
  const ValidationReport limited = checkConvexBlock(mesh, 1e-9, 5);
  CHECK(limited.problems.size() == 5);
  CHECK(limited.truncated);
  CHECK_THAT(limited.problems[4].message, StartsWith("vertex 4 has a non-finite coordinate"));
  CHECK(toString(MeshProblemKind::NotConvex) == "not convex");
  CHECK(toString(MeshProblemKind::OpenEdge) == "open edge");
}
