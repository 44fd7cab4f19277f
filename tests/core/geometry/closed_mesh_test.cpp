// validateClosedMesh / checkClosedMesh: closed meshes of any genus and several shells pass; each
// kind of bad mesh is refused with its message, which says what to do. The self-intersection
// search is compared with CGAL in closed_mesh_cgal_test.cpp.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core_test_support.hpp"
#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/self_intersection.hpp"
#include "test_shapes.hpp"

using namespace recode::core;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using recode::core::test::joined;
using recode::core::test::makeTorus;
using recode::core::test::meshErrorMessage;
using recode::core::test::placed;
using recode::core::test::reversed;

namespace {

std::string closedMessage(const TriangleMesh& mesh) {
  return meshErrorMessage([&] { validateClosedMesh(mesh, "m"); });
}

// The kinds of the problems found, in order.
std::vector<MeshProblemKind> kinds(const ValidationReport& report) {
  std::vector<MeshProblemKind> out;
  for (const MeshProblem& p : report.problems) {
    out.push_back(p.kind);
  }
  return out;
}

MeshProblemKind firstKind(const TriangleMesh& mesh) {
  const ValidationReport report = checkClosedMesh(mesh);
  REQUIRE_FALSE(report.ok());
  return report.problems.front().kind;
}

// A tetrahedron with outward faces over vertices first .. first + 3.
void addTetrahedron(TriangleMesh& mesh, const std::array<Eigen::Vector3d, 4>& corners) {
  const auto v = static_cast<VertexIndex>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), corners.begin(), corners.end());
  mesh.triangles.push_back({v, v + 2, v + 1});
  mesh.triangles.push_back({v, v + 1, v + 3});
  mesh.triangles.push_back({v, v + 3, v + 2});
  mesh.triangles.push_back({v + 1, v + 2, v + 3});
}

const std::array<Eigen::Vector3d, 4> kTetrahedron = {
    Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
    Eigen::Vector3d(0, 0, 1)};

}  // namespace

TEST_CASE("closed meshes of any genus and several shells pass", "[closed_mesh]") {
  CHECK(checkClosedMesh(makeBox(1.0, 2.0, 3.0)).ok());
  CHECK(checkClosedMesh(makeSphere(1.0, 48, 24)).ok());
  CHECK(checkClosedMesh(makeCappedCone(1.0, 0.2, 4.0, 48, 12)).ok());
  // Genus 1, and a non-convex one that the convex-block check refuses.
  const TriangleMesh torus = makeTorus(24, 12);
  CHECK(checkClosedMesh(torus).ok());
  CHECK_FALSE(checkConvexBlock(torus).ok());
  // Two disjoint solids; two linked rings (the second in the xz plane through the first's hole).
  CHECK(checkClosedMesh(joined(makeBox(1, 1, 1), placed(makeSphere(1, 16, 8), {5, 0, 0}))).ok());
  TriangleMesh ring = makeTorus(32, 12);
  for (Eigen::Vector3d& p : ring.vertices) {
    p = Eigen::Vector3d(p.x() + 2.0, p.z(), -p.y());
  }
  CHECK(checkClosedMesh(joined(torus, ring)).ok());
  // A box with a cavity (the inner shell faces inward), and an island inside the cavity.
  const TriangleMesh hollow = joined(makeBox(2, 2, 2), reversed(makeBox(1, 1, 1)));
  CHECK(checkClosedMesh(hollow).ok());
  CHECK(checkClosedMesh(joined(hollow, makeSphere(0.5, 12, 6))).ok());
  // Unused vertices are not part of the surface.
  TriangleMesh stray = makeBox(1, 1, 1);
  stray.vertices.emplace_back(7, 7, 7);
  CHECK(checkClosedMesh(stray).ok());
}

TEST_CASE("closed meshes: input problems", "[closed_mesh]") {
  CHECK(closedMessage(TriangleMesh{}) ==
        "m: the mesh has no triangles; a closed mesh needs the triangles of at least one closed "
        "surface");

  TriangleMesh nan = makeBox(1, 1, 1);
  nan.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK(closedMessage(nan) ==
        "m: vertex 3 has a non-finite coordinate (nan, 1, -1); fix or remove that vertex");

  TriangleMesh huge = makeBox(1, 1, 1);
  huge.vertices[5] *= 1e101;
  CHECK_THAT(closedMessage(huge), StartsWith("m: vertex 5 (") &&
                                      Contains("has a coordinate beyond +-1e100") &&
                                      Contains("scale the mesh down"));
  CHECK(firstKind(huge) == MeshProblemKind::CoordinateOutOfRange);
  huge.vertices[5] = {1e100, -1e100, 1e100};  // the limit itself is accepted
  for (const MeshProblem& p : checkClosedMesh(huge).problems) {
    CHECK(p.kind != MeshProblemKind::CoordinateOutOfRange);
  }

  TriangleMesh index = makeBox(1, 1, 1);
  index.triangles[4][1] = 99;
  CHECK(closedMessage(index) ==
        "m: triangle 4 has vertex index 99 out of range (8 vertices); every index must name one "
        "of the vertices (counted from 0)");
}

TEST_CASE("closed meshes: degenerate triangles are decided exactly", "[closed_mesh]") {
  TriangleMesh line;
  line.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
  line.triangles = {{0, 1, 2}};
  const ValidationReport report = checkClosedMesh(line);
  REQUIRE_FALSE(report.ok());
  CHECK(report.problems[0].kind == MeshProblemKind::DegenerateTriangle);
  CHECK(report.problems[0].message ==
        "triangle 0 (vertices 0, 1, 2) has zero area: its three points lie on one line; remove it "
        "(merge it into its neighbours) or move a vertex off the line");
  // Stage 4 runs beside stage 3: the lone triangle's edges are open too.
  CHECK(kinds(report).back() == MeshProblemKind::OpenEdge);

  line.triangles = {{0, 2, 0}};
  CHECK_THAT(checkClosedMesh(line).problems[0].message,
             StartsWith("triangle 0 (vertices 0, 2, 0) repeats vertex index 0; remove it"));

  // One ulp off the line is a triangle, however thin: no tolerance.
  line.vertices[2].z() = std::nextafter(3.0, 4.0);
  line.triangles = {{0, 1, 2}};
  for (const MeshProblem& p : checkClosedMesh(line).problems) {
    CHECK(p.kind != MeshProblemKind::DegenerateTriangle);
  }
}

TEST_CASE("closed meshes: open, non-manifold and inconsistently oriented edges", "[closed_mesh]") {
  TriangleMesh open = makeBox(1, 1, 1);
  open.triangles.pop_back();
  CHECK_THAT(closedMessage(open),
             StartsWith("m: edge (") && Contains("is used by only one triangle (triangle ") &&
                 Contains("the mesh is not closed; fill the hole so that every edge has a "
                          "triangle on each side"));

  // Two tetrahedra on the same edge (0, 1): it is used by four triangles.
  TriangleMesh wings;
  addTetrahedron(wings, kTetrahedron);
  wings.vertices.emplace_back(0, -1, 0);
  wings.vertices.emplace_back(0, 0, -1);
  wings.triangles.push_back({0, 4, 1});
  wings.triangles.push_back({0, 1, 5});
  wings.triangles.push_back({0, 5, 4});
  wings.triangles.push_back({1, 4, 5});
  CHECK(closedMessage(wings) ==
        "m: edge (0, 1) is used by 4 triangles (triangles 0, 1, 4, 5); a closed surface uses it "
        "twice; separate the surfaces that meet there so that each edge joins two triangles");

  TriangleMesh flipped;
  addTetrahedron(flipped, kTetrahedron);
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);  // (1, 3, 2)
  CHECK(closedMessage(flipped) ==
        "m: edge (1, 2) is used twice in the same direction (triangles 0 and 3): inconsistent "
        "orientation; reverse the winding of one of the two (swap two of its indices) so that "
        "all triangles of a piece face the same way");
}

TEST_CASE("closed meshes: a vertex where separate fans meet", "[closed_mesh]") {
  // Two tetrahedra tip to tip, sharing vertex 0 only.
  TriangleMesh pinched;
  addTetrahedron(pinched, kTetrahedron);
  pinched.vertices.emplace_back(-1, 0, 0);
  pinched.vertices.emplace_back(0, -1, 0);
  pinched.vertices.emplace_back(0, 0, -1);
  // The mirror image of the first (through the origin), wound to face outward.
  pinched.triangles.push_back({0, 4, 5});
  pinched.triangles.push_back({0, 6, 4});
  pinched.triangles.push_back({0, 5, 6});
  pinched.triangles.push_back({4, 6, 5});
  CHECK(closedMessage(pinched) ==
        "m: vertex 0 is shared by 2 separate fans of triangles (triangles 0 and 4 are in "
        "different fans): the surface pinches there; give each fan a vertex of its own and move "
        "them apart, or join the pieces");
  // With a vertex of its own at the same place, the second tetrahedron touches the first.
  pinched.vertices.emplace_back(0, 0, 0);
  for (std::size_t t = 4; t < 8; ++t) {
    for (VertexIndex& v : pinched.triangles[t]) {
      v = v == 0 ? 7 : v;
    }
  }
  CHECK(firstKind(pinched) == MeshProblemKind::SelfIntersection);
}

TEST_CASE("closed meshes: self-intersections name a pair of triangles", "[closed_mesh]") {
  const TriangleMesh box = makeBox(1, 1, 1);
  // Overlapping solids.
  const ValidationReport overlap = checkClosedMesh(joined(box, placed(box, {0.5, 0.3, 0.2})), 4);
  REQUIRE(overlap.problems.size() == 4);
  CHECK(overlap.truncated);
  for (const MeshProblem& p : overlap.problems) {
    CHECK(p.kind == MeshProblemKind::SelfIntersection);
    CHECK_THAT(p.message, Contains(") intersect; a closed mesh must not cut, touch or overlap "
                                   "itself: separate or remesh the parts that meet"));
  }
  // Touching at a corner (vertex 7 of the first, (1, 1, 1), is vertex 0 of the second), along
  // an edge, in a face (coplanar faces overlapping): each is a self-intersection, and moving
  // the second box away by one ulp leaves none.
  for (const Eigen::Vector3d& offset :
       {Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2, 2, 0.5), Eigen::Vector3d(2, 0.5, 0.25)}) {
    CAPTURE(offset);
    const TriangleMesh touching = joined(box, placed(box, offset));
    CHECK(firstKind(touching) == MeshProblemKind::SelfIntersection);
    const TrianglePair first = selfIntersections(touching).front();
    CHECK(first.first < 12);
    CHECK(first.second >= 12);
    const Eigen::Vector3d apart(std::nextafter(offset.x(), 3.0), offset.y(), offset.z());
    CHECK(checkClosedMesh(joined(box, placed(box, apart))).ok());
  }
  // An edge of a long thin tetrahedron through two faces of the box, no vertex inside it.
  TriangleMesh pierced = box;
  addTetrahedron(pierced, {Eigen::Vector3d(-3, 0, 0), Eigen::Vector3d(3, 0, 0),
                           Eigen::Vector3d(0, 0.1, 3), Eigen::Vector3d(0, -0.1, 3)});
  const std::vector<TrianglePair> pairs = selfIntersections(pierced);
  REQUIRE_FALSE(pairs.empty());
  for (const TrianglePair& pair : pairs) {
    CHECK(pair.first < 12);
    CHECK(pair.second >= 12);
  }
}

TEST_CASE("closed meshes: a surface folded onto itself or doubled", "[closed_mesh]") {
  // A tetrahedron flattened into the plane z = 0: closed and consistently wound, but triangles
  // 0 and 1 lie on the same side of their shared edge (0, 1).
  TriangleMesh flat;
  addTetrahedron(flat, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                        Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0)});
  CHECK(closedMessage(flat) ==
        "m: triangle 0 (vertices 0, 2, 1) and triangle 1 (vertices 0, 1, 3) lie in one plane on "
        "the same side of the edge they share: the surface folds onto itself; a closed mesh must "
        "not cut, touch or overlap itself: separate or remesh the parts that meet");
  // Lifting vertex 3 off the plane unfolds it.
  flat.vertices[3].z() = 1e-30;
  CHECK(checkClosedMesh(flat).ok());

  // Two copies of one triangle, wound opposite ways: every edge used once each way.
  TriangleMesh doubled;
  doubled.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  doubled.triangles = {{0, 1, 2}, {0, 2, 1}};
  CHECK(closedMessage(doubled) ==
        "m: triangle 0 (vertices 0, 1, 2) and triangle 1 (vertices 0, 2, 1) have the same three "
        "vertices: the surface doubles back on itself; a closed mesh must not cut, touch or "
        "overlap itself: separate or remesh the parts that meet");

  // Triangles sharing one vertex and crossing: an octahedron whose top vertex is pulled down
  // through its lower half, so that its fan cuts the lower fan.
  TriangleMesh octahedron = makeSphere(1.0, 4, 2);
  REQUIRE(octahedron.vertexCount() == 6);
  octahedron.vertices[5] = {0.9, 0.0, -0.5};
  const ValidationReport report = checkClosedMesh(octahedron, 64);
  CHECK(kinds(report) ==
        std::vector<MeshProblemKind>(report.problems.size(), MeshProblemKind::SelfIntersection));
  bool beyondSharedVertex = false;
  for (const MeshProblem& p : report.problems) {
    beyondSharedVertex |= p.message.find("meet beyond the vertex they share") != std::string::npos;
  }
  CHECK(beyondSharedVertex);
}

TEST_CASE("closed meshes: shells face away from the solid they bound", "[closed_mesh]") {
  CHECK(closedMessage(reversed(makeBox(1, 1, 1))) ==
        "m: signed volume is -8 (must be > 0): the faces point inward; reverse the winding of "
        "every triangle (swap two indices of each)");

  const TriangleMesh outer = makeBox(2, 2, 2);
  const TriangleMesh inner = makeBox(0.5, 0.5, 0.5);
  // A second, disjoint shell inside out.
  CHECK(closedMessage(joined(outer, reversed(placed(inner, {5, 0, 0})))) ==
        "m: the shell of triangle 12 (12 triangles; the mesh has 2 shells) has signed volume -1 "
        "and lies inside no other shell: its faces point inward; reverse the winding of its "
        "triangles (swap two indices of each)");
  // An outward shell inside the solid.
  CHECK(closedMessage(joined(outer, inner)) ==
        "m: the shell of triangle 12 (12 triangles; the mesh has 2 shells) faces outward (signed "
        "volume 1) but lies inside the solid of the others (its vertex 8 has winding number 1): "
        "that space would be solid twice; if it bounds a cavity, reverse the winding of its "
        "triangles (swap two indices of each), else remove it or move it out");
  // Three outward shells nested: the middle one is inside one solid, the innermost inside two.
  const ValidationReport three =
      checkClosedMesh(joined(joined(outer, makeBox(1, 1, 1)), makeBox(0.25, 0.25, 0.25)));
  REQUIRE(kinds(three) ==
          std::vector<MeshProblemKind>{MeshProblemKind::NestedShell, MeshProblemKind::NestedShell});
  CHECK_THAT(three.problems[0].message, StartsWith("the shell of triangle 12 "));
  CHECK_THAT(three.problems[1].message,
             StartsWith("the other shells wind 2 times around the shell of triangle 24 (12 "
                        "triangles; the mesh has 3 shells) (at its vertex 16)"));
  // Two inward shells nested: the outer is inside out, the inner wound -1 times.
  const ValidationReport inward = checkClosedMesh(joined(reversed(outer), reversed(inner)));
  CHECK(kinds(inward) == std::vector<MeshProblemKind>{MeshProblemKind::InwardOrientation,
                                                      MeshProblemKind::NestedShell});
  // The winding is counted along a ray from the shell's first vertex; here the ray from the
  // inner box's corner (-1, -1, -1) meets the outer box's side x = 2 on the diagonal edge
  // between its two triangles, and the crossing still counts once.
  const TriangleMesh aligned = joined(makeBox(2, 2, 2), placed(makeBox(2, 2, 2), {0, 0, 0}, 0.5));
  CHECK(firstKind(aligned) == MeshProblemKind::NestedShell);
  CHECK(
      checkClosedMesh(joined(makeBox(2, 2, 2), reversed(placed(makeBox(2, 2, 2), {0, 0, 0}, 0.5))))
          .ok());
}

TEST_CASE("closed meshes: arguments", "[closed_mesh]") {
  CHECK_THROWS_AS(checkClosedMesh(makeBox(1, 1, 1), 0), std::invalid_argument);
  TriangleMesh line;
  line.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
  line.triangles = {{0, 1, 2}};
  CHECK_THROWS_AS(selfIntersections(line), std::invalid_argument);
  CHECK(toString(MeshProblemKind::SelfIntersection) == "self-intersection");
  CHECK(toString(MeshProblemKind::NestedShell) == "nested shell");
  CHECK(toString(MeshProblemKind::NonManifoldVertex) == "non-manifold vertex");
  CHECK(toString(MeshProblemKind::CoordinateOutOfRange) == "coordinate out of range");
}
