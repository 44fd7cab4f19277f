// The exact self-intersection search (self_intersection.hpp) and the closed-mesh check
// (closed_mesh.hpp) against CGAL: the same intersecting pairs of triangles as
// CGAL::Polygon_mesh_processing::self_intersections on many random and adversarial meshes
// (solids on a small integer grid that touch at vertices, along edges and in coplanar faces;
// small meshes with vertices snapped to a grid, folding and crossing themselves; rotated copies),
// and the same verdicts on CGAL's demo meshes (closed, outward, self-intersecting). Built only
// with CGAL (RECODE_WITH_CGAL); the geometry library itself never uses it.

#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/geometry/self_intersection.hpp"
#include "test_shapes.hpp"

namespace recode::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<Kernel::Point_3>;
using Face = Surface::Face_index;
namespace PMP = CGAL::Polygon_mesh_processing;
using test::joined;
using test::placed;

// The mesh as a CGAL surface, face k being triangle k; nothing if CGAL cannot hold it as a
// manifold surface (an edge used by more than two faces, a pinched vertex, ...).
std::optional<Surface> toSurface(const TriangleMesh& mesh) {
  Surface surface;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    surface.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  }
  for (const Triangle& t : mesh.triangles) {
    const Face f = surface.add_face(Surface::Vertex_index(t[0]), Surface::Vertex_index(t[1]),
                                    Surface::Vertex_index(t[2]));
    if (f == Surface::null_face()) {
      return std::nullopt;
    }
  }
  return surface;
}

std::vector<TrianglePair> cgalPairs(const Surface& surface) {
  std::vector<std::pair<Face, Face>> found;
  PMP::self_intersections(surface, std::back_inserter(found));
  std::vector<TrianglePair> pairs;
  for (const auto& [f, g] : found) {
    const auto a = static_cast<std::uint32_t>(f.idx());
    const auto b = static_cast<std::uint32_t>(g.idx());
    pairs.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(pairs.begin(), pairs.end(), [](const TrianglePair& l, const TrianglePair& r) {
    return l.first < r.first || (l.first == r.first && l.second < r.second);
  });
  return pairs;
}

bool isDegenerate(const TriangleMesh& mesh) {
  for (const MeshProblem& p : checkClosedMesh(mesh, 1).problems) {
    if (p.kind == MeshProblemKind::DegenerateTriangle) {
      return true;
    }
  }
  return false;
}

// Counts what the comparisons saw, over a family.
struct Tally {
  int compared = 0;
  int intersecting = 0;
  int sharedVertexOrEdgeOnly = 0;  // every intersecting pair shares a vertex index
};

// Compares one mesh's intersecting pairs with CGAL's. Meshes CGAL cannot hold or with a
// degenerate triangle (outside both searches' preconditions) are skipped.
void compare(const TriangleMesh& mesh, const std::string& what, Tally& tally) {
  INFO(what);
  if (isDegenerate(mesh)) {
    return;
  }
  const std::optional<Surface> surface = toSurface(mesh);
  if (!surface) {
    return;
  }
  const std::vector<TrianglePair> ours = selfIntersections(mesh);
  const std::vector<TrianglePair> theirs = cgalPairs(*surface);
  REQUIRE(ours.size() == theirs.size());
  CHECK(ours == theirs);
  CHECK(PMP::does_self_intersect(*surface) == !ours.empty());
  ++tally.compared;
  if (!ours.empty()) {
    ++tally.intersecting;
  }
}

// A tetrahedron with positive volume on four grid points, or nothing if they are coplanar.
std::optional<TriangleMesh> gridTetrahedron(std::mt19937& rng, int size) {
  std::uniform_int_distribution<int> coordinate(0, size);
  TriangleMesh tet;
  for (int k = 0; k < 4; ++k) {
    tet.vertices.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
  }
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const double volume = signedVolume(tet);
  if (volume == 0.0) {
    return std::nullopt;
  }
  return volume > 0.0 ? tet : test::reversed(tet);
}

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

TriangleMesh rotated(TriangleMesh mesh, const Eigen::Matrix3d& rotation) {
  for (Eigen::Vector3d& p : mesh.vertices) {
    p = rotation * p;
  }
  return mesh;
}

}  // namespace

TEST_CASE("self-intersections: tetrahedra on a small grid touch and overlap as CGAL finds",
          "[closed_mesh][cgal]") {
  std::mt19937 rng(20261207);
  Tally tally;
  for (int round = 0; round < 400; ++round) {
    TriangleMesh soup;
    const int count = 2 + round % 4;
    for (int k = 0; k < count; ++k) {
      if (const std::optional<TriangleMesh> tet = gridTetrahedron(rng, 2 + round % 3)) {
        soup = joined(soup, *tet);
      }
    }
    if (soup.triangles.empty()) {
      continue;
    }
    compare(soup, "grid tetrahedra, round " + std::to_string(round), tally);
    if (round % 4 == 0) {
      compare(rotated(soup, randomRotation(rng)), "rotated, round " + std::to_string(round), tally);
    }
  }
  CHECK(tally.compared > 450);
  CHECK(tally.intersecting > 200);
  CHECK(tally.compared - tally.intersecting > 20);
}

TEST_CASE(
    "self-intersections: boxes on a half-unit grid share faces, edges and corners as CGAL "
    "finds",
    "[closed_mesh][cgal]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> half(1, 3), offset(-3, 3);
  Tally tally;
  for (int round = 0; round < 300; ++round) {
    TriangleMesh boxes;
    for (int k = 0; k < 3; ++k) {
      const TriangleMesh box = makeBox(0.5 * half(rng), 0.5 * half(rng), 0.5 * half(rng));
      boxes = joined(boxes, placed(box, {0.5 * offset(rng), 0.5 * offset(rng), 0.5 * offset(rng)}));
    }
    compare(boxes, "boxes, round " + std::to_string(round), tally);
  }
  CHECK(tally.compared == 300);
  CHECK(tally.intersecting > 100);
}

TEST_CASE("self-intersections: small meshes folded onto and through themselves as CGAL finds",
          "[closed_mesh][cgal]") {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> grid(-2, 2);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Tally tally;
  const std::vector<TriangleMesh> shapes = {makeSphere(1.0, 4, 2), makeSphere(1.0, 6, 4),
                                            makeBox(1, 1, 1), makeCone(1, 1, 5),
                                            test::makeTorus(6, 4)};
  for (int round = 0; round < 600; ++round) {
    TriangleMesh mesh = shapes[static_cast<std::size_t>(round) % shapes.size()];
    // Snap some vertices to a small grid (coplanar folds, vertices on faces and edges) or, every
    // third round, move them in general position (crossings).
    for (Eigen::Vector3d& p : mesh.vertices) {
      if (round % 3 == 2) {
        p += 0.8 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      } else if (grid(rng) >= 0) {
        p = Eigen::Vector3d(grid(rng), grid(rng), grid(rng)) * 0.5;
      }
    }
    compare(mesh, "folded shape, round " + std::to_string(round), tally);
  }
  CHECK(tally.compared > 300);
  CHECK(tally.intersecting > 100);
}

TEST_CASE("self-intersections: the named adversarial cases agree with CGAL",
          "[closed_mesh][cgal]") {
  Tally tally;
  const TriangleMesh box = makeBox(1, 1, 1);
  compare(joined(box, placed(box, {2, 2, 2})), "touching at a vertex", tally);
  compare(joined(box, placed(box, {2, 2, 0.5})), "touching along an edge", tally);
  compare(joined(box, placed(box, {2, 0.5, 0.25})), "coplanar overlapping faces", tally);
  compare(joined(box, placed(box, {2, 0, 0})), "coplanar, one face on the other", tally);
  TriangleMesh pierced = box;
  pierced.vertices.insert(pierced.vertices.end(),
                          {{-3, 0, 0}, {3, 0, 0}, {0, 0.1, 3}, {0, -0.1, 3}});
  for (const Triangle& t :
       std::vector<Triangle>{{8, 10, 9}, {8, 9, 11}, {8, 11, 10}, {9, 10, 11}}) {
    pierced.triangles.push_back(t);
  }
  compare(pierced, "an edge through two faces", tally);
  TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  flat.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  compare(flat, "a pair sharing an edge folded onto itself", tally);
  TriangleMesh octahedron = makeSphere(1.0, 4, 2);
  octahedron.vertices[5] = {0.9, 0.0, -0.5};
  compare(octahedron, "triangles sharing a vertex crossing", tally);
  CHECK(tally.compared == 7);
  CHECK(tally.intersecting == 7);
}

// CGAL's demo meshes (Debian package libcgal-demo), extracted from its data archive by the test
// fixture into RECODE_CGAL_DEMO_DIR.
namespace {

struct DemoVerdict {
  std::string name;
  std::size_t triangles = 0;
  std::string ours;  // "ok" or the first problem's kind
  std::string cgal;  // closed / outward / self-intersecting, or why CGAL cannot hold it
};

std::filesystem::path demoDir() {
  return std::filesystem::path(RECODE_CGAL_DEMO_DIR);
}

// CGAL's view of a mesh: whether it can hold it, is closed, outward, self-intersecting.
std::string cgalVerdict(const TriangleMesh& mesh, bool& intersects) {
  intersects = false;
  const std::optional<Surface> surface = toSurface(mesh);
  if (!surface) {
    return "not a manifold surface";
  }
  if (!CGAL::is_closed(*surface)) {
    return "open";
  }
  intersects = PMP::does_self_intersect(*surface);
  if (intersects) {
    return "self-intersecting";
  }
  return PMP::is_outward_oriented(*surface) ? "closed, outward" : "closed, inward";
}

// The names of the meshes compared: the archive paths of tests/core/geometry/cgal_demo_meshes.txt
// (the fixture unpacks the same list), without folder and extension.
std::vector<std::string> demoMeshes() {
  std::ifstream list(RECODE_CGAL_DEMO_LIST);
  std::vector<std::string> names;
  for (std::string line; std::getline(list, line);) {
    if (!line.empty()) {
      names.push_back(std::filesystem::path(line).stem().string());
    }
  }
  return names;
}

}  // namespace

TEST_CASE("closed meshes: CGAL's demo meshes get the same verdicts as from CGAL",
          "[closed_mesh][cgal][demo]") {
  if (std::string(RECODE_CGAL_DEMO_DIR).empty() || !std::filesystem::exists(demoDir())) {
    WARN("CGAL's demo meshes are not installed (Debian package libcgal-demo): not compared");
    return;
  }
  int closedAndClean = 0;
  for (const std::string& name : demoMeshes()) {
    const std::filesystem::path path = demoDir() / (name + ".off");
    INFO(name);
    REQUIRE(std::filesystem::exists(path));
    const TriangleMesh mesh = readOff(path);
    const ValidationReport report = checkClosedMesh(mesh, 1);
    bool intersects = false;
    const std::string cgal = cgalVerdict(mesh, intersects);
    const std::string ours =
        report.ok() ? "ok" : std::string(toString(report.problems.front().kind));
    UNSCOPED_INFO(name << ": " << mesh.triangleCount() << " triangles; ours: " << ours
                       << "; CGAL: " << cgal);
    if (report.ok()) {
      ++closedAndClean;
      CHECK(cgal == "closed, outward");
    } else {
      const MeshProblemKind kind = report.problems.front().kind;
      if (kind == MeshProblemKind::OpenEdge) {
        CHECK(cgal == "open");
      } else if (kind == MeshProblemKind::SelfIntersection) {
        CHECK(intersects);
        CHECK(selfIntersections(mesh) == cgalPairs(*toSurface(mesh)));
      } else if (kind == MeshProblemKind::InwardOrientation) {
        CHECK(cgal == "closed, inward");
      } else {
        CHECK(cgal == "not a manifold surface");
      }
    }
  }
  CHECK(closedAndClean >= 10);
}

// Not run by ctest: the cost of the self-intersection search and of the whole check on the
// demo meshes, beside CGAL's does_self_intersect (docs/geometry.md quotes the figures).
// recode_geometry_cgal_tests "[.closed_mesh_timing]"
TEST_CASE("closed meshes: timing on CGAL's demo meshes", "[.closed_mesh_timing]") {
  using Clock = std::chrono::steady_clock;
  const auto best = [](const auto& run) {
    double fastest = 1e300;
    for (int k = 0; k < 3; ++k) {
      const auto start = Clock::now();
      run();
      fastest = std::min(fastest, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return fastest;
  };
  std::printf(
      "| mesh | triangles | selfIntersections | checkClosedMesh | CGAL does_self_intersect |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const std::string& name : demoMeshes()) {
    const TriangleMesh mesh = readOff(demoDir() / (name + ".off"));
    const ValidationReport report = checkClosedMesh(mesh, 1);
    if (!report.ok()) {
      continue;
    }
    const Surface surface = *toSurface(mesh);
    const double search = best([&] { (void)selfIntersections(mesh, 1); });
    const double check = best([&] { (void)checkClosedMesh(mesh, 1); });
    const double cgal = best([&] { (void)PMP::does_self_intersect(surface); });
    std::printf("| %s | %zu | %.1f ms | %.1f ms | %.1f ms |\n", name.c_str(), mesh.triangleCount(),
                1e3 * search, 1e3 * check, 1e3 * cgal);
  }
  for (const int segments : {256, 1024}) {
    const TriangleMesh sphere = makeSphere(1.0, segments, segments / 2);
    const Surface surface = *toSurface(sphere);
    std::printf("| makeSphere(1, %d, %d) | %zu | %.1f ms | %.1f ms | %.1f ms |\n", segments,
                segments / 2, sphere.triangleCount(),
                1e3 * best([&] { (void)selfIntersections(sphere, 1); }),
                1e3 * best([&] { (void)checkClosedMesh(sphere, 1); }),
                1e3 * best([&] { (void)PMP::does_self_intersect(surface); }));
  }
}

}  // namespace recode::core
