// The exact intersection of two convex blocks, the only translation unit that includes CGAL
// (it compiles slowly: keep it the only one). Method (docs/verification.md, "The CGAL oracle"):
//
// - The verdict is CGAL's Polygon_mesh_processing::do_intersect with the bounded-side test, so
//   that one block inside the other counts, on Epeck copies of the meshes (their double
//   coordinates are exact rationals there).
// - The solid: every vertex of P = A ∩ B is a vertex of one block lying in the other (closed)
//   or a point where an edge of one block meets a triangle of the other. (Take the smallest
//   faces of A and B holding such a vertex in their relative interiors: their affine hulls meet
//   in that point alone, so their dimensions add up to at most 3: vertex + anything, or edge +
//   edge, or edge + face; an edge of one block crossing an edge of the other also crosses a
//   triangle beside that edge.) All these points are constructed exactly; their box is the
//   solid's box, and the volume of their convex hull is the solid's volume (the blocks are
//   convex). This also covers touching contacts, where a corefinement would give an empty or
//   degenerate solid.
// - The two methods cross-check each other: the point set is empty exactly when do_intersect
//   says the blocks are apart.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "recode/geometry/validate.hpp"
#include "recode/verify/cgal_oracle.hpp"

#include "cgal_exact_mesh.hpp"

namespace recode::verify {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Mesh = cgal::ExactMesh;
using cgal::toExactMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<Triangle> trianglesOf(const Mesh& mesh) {
  std::vector<Triangle> out;
  out.reserve(mesh.number_of_faces());
  for (const Mesh::Face_index f : mesh.faces()) {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    out.emplace_back(mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h))),
                     mesh.point(mesh.target(mesh.next(mesh.next(h)))));
  }
  return out;
}

// Points where an edge of `edges` meets a triangle of `faces` (both ends of the common segment
// where an edge lies in a triangle's plane).
void addEdgeCrossings(const Mesh& edges, const std::vector<Triangle>& faces,
                      std::vector<Point>& out) {
  std::vector<CGAL::Bbox_3> faceBoxes;
  faceBoxes.reserve(faces.size());
  for (const Triangle& t : faces)
    faceBoxes.push_back(t.bbox());
  for (const Mesh::Edge_index e : edges.edges()) {
    const Mesh::Halfedge_index h = edges.halfedge(e);
    const Segment s(edges.point(edges.source(h)), edges.point(edges.target(h)));
    const CGAL::Bbox_3 box = s.bbox();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!CGAL::do_overlap(box, faceBoxes[f]) || !CGAL::do_intersect(s, faces[f]))
        continue;
      const auto hit = CGAL::intersection(s, faces[f]);
      if (!hit)
        continue;
      if (const Point* p = boost::get<Point>(&*hit)) {
        out.push_back(*p);
      } else if (const Segment* q = boost::get<Segment>(&*hit)) {
        out.push_back(q->source());
        out.push_back(q->target());
      }
    }
  }
}

// Vertices of `inner` in the closed solid bounded by `outer`.
void addVerticesInside(const Mesh& inner, const Mesh& outer, std::vector<Point>& out) {
  const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(outer);
  for (const Mesh::Vertex_index v : inner.vertices())
    if (side(inner.point(v)) != CGAL::ON_UNBOUNDED_SIDE)
      out.push_back(inner.point(v));
}

// Volume of the convex hull of distinct points: 0 unless four of them span a solid.
double hullVolume(const std::vector<Point>& points) {
  if (points.size() < 4)
    return 0.0;
  const Point& p0 = points[0];
  const Point& p1 = points[1];
  auto third = std::find_if(points.begin() + 2, points.end(),
                            [&](const Point& p) { return !CGAL::collinear(p0, p1, p); });
  if (third == points.end())
    return 0.0;
  const Point& p2 = *third;
  if (std::all_of(points.begin(), points.end(),
                  [&](const Point& p) { return CGAL::coplanar(p0, p1, p2, p); }))
    return 0.0;
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  return CGAL::to_double(CGAL::exact(PMP::volume(hull)));
}

// The two blocks, checked and copied exactly: the common start of both entry points.
struct ExactPair {
  Mesh a;
  Mesh b;
};

ExactPair toExactPair(const core::TriangleMesh& worldA, const core::TriangleMesh& worldB) {
  core::validateConvexBlock(worldA, "block A");
  core::validateConvexBlock(worldB, "block B");
  return {toExactMesh(worldA, "block A"), toExactMesh(worldB, "block B")};
}

// The verdict on closed sets: surfaces that meet (touching included), or one block's bounded
// side holding the other (containment, where no surfaces meet).
bool closedSolidsIntersect(const Mesh& a, const Mesh& b) {
  return PMP::do_intersect(a, b, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                           CGAL::parameters::do_overlap_test_of_bounded_sides(true));
}

// Every vertex of A ∩ B, exactly (the method in this file's head comment), sorted and distinct.
std::vector<Point> intersectionPoints(const ExactPair& pair) {
  std::vector<Point> points;
  addEdgeCrossings(pair.a, trianglesOf(pair.b), points);
  addEdgeCrossings(pair.b, trianglesOf(pair.a), points);
  addVerticesInside(pair.a, pair.b, points);
  addVerticesInside(pair.b, pair.a, points);
  std::sort(points.begin(), points.end(), Kernel::Less_xyz_3());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

}  // namespace

core::TriangleMesh intersectionHull(const core::TriangleMesh& worldA,
                                    const core::TriangleMesh& worldB) {
  const std::vector<Point> points = intersectionPoints(toExactPair(worldA, worldB));
  core::TriangleMesh out;
  if (hullVolume(points) <= 0.0)
    return out;
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  std::vector<std::uint32_t> index(hull.number_of_vertices());
  for (const Mesh::Vertex_index v : hull.vertices()) {
    const Point& p = hull.point(v);
    index[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                              CGAL::to_double(p.z()));
  }
  for (const Mesh::Face_index f : hull.faces()) {
    const Mesh::Halfedge_index h = hull.halfedge(f);
    out.triangles.push_back({index[hull.target(h).idx()], index[hull.target(hull.next(h)).idx()],
                             index[hull.target(hull.next(hull.next(h))).idx()]});
  }
  return out;
}

bool exactlyIntersect(const core::TriangleMesh& worldA, const core::TriangleMesh& worldB) {
  const ExactPair pair = toExactPair(worldA, worldB);
  return closedSolidsIntersect(pair.a, pair.b);
}

bool grownBlockMeets(const core::TriangleMesh& worldA, const Eigen::Vector3d& half,
                     const core::TriangleMesh& worldB) {
  const ExactPair pair = toExactPair(worldA, worldB);
  std::vector<Point> sums;
  sums.reserve(8 * worldA.vertices.size());
  for (const Eigen::Vector3d& v : worldA.vertices)
    for (int c = 0; c < 8; ++c)
      sums.emplace_back(Kernel::FT(v.x()) + Kernel::FT((c & 1 ? 1 : -1) * half.x()),
                        Kernel::FT(v.y()) + Kernel::FT((c & 2 ? 1 : -1) * half.y()),
                        Kernel::FT(v.z()) + Kernel::FT((c & 4 ? 1 : -1) * half.z()));
  Mesh grown;
  CGAL::convex_hull_3(sums.begin(), sums.end(), grown);
  return closedSolidsIntersect(grown, pair.b);
}

ExactIntersection exactIntersection(const core::TriangleMesh& worldA,
                                    const core::TriangleMesh& worldB) {
  const ExactPair pair = toExactPair(worldA, worldB);
  const Mesh& a = pair.a;
  const Mesh& b = pair.b;

  const bool overlap = closedSolidsIntersect(a, b);

  std::vector<Point> points;
  addEdgeCrossings(a, trianglesOf(b), points);
  addEdgeCrossings(b, trianglesOf(a), points);
  addVerticesInside(a, b, points);
  addVerticesInside(b, a, points);
  std::sort(points.begin(), points.end(), Kernel::Less_xyz_3());
  points.erase(std::unique(points.begin(), points.end()), points.end());

  if (overlap == points.empty())
    throw std::logic_error(std::string("CGAL oracle: do_intersect says the blocks ") +
                           (overlap ? "intersect" : "are apart") + " but " +
                           std::to_string(points.size()) +
                           " exact points lie in both; one of the two exact methods is wrong");

  ExactIntersection r;
  r.intersect = overlap;
  r.boundaryPoints = static_cast<long long>(points.size());
  for (const Point& p : points) {
    // Intervals of the exact coordinates: their lower and upper ends round the box outward.
    for (int k = 0; k < 3; ++k) {
      const std::pair<double, double> range = CGAL::to_interval(CGAL::exact(p[k]));
      r.box.min[k] = std::min(r.box.min[k], range.first);
      r.box.max[k] = std::max(r.box.max[k], range.second);
    }
  }
  r.volume = hullVolume(points);
  return r;
}

}  // namespace recode::verify
