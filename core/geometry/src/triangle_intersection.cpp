// Exact tests of closed segments and triangles in 3-D, built on orient3d and orient2d alone, so
// that every answer is that of the exact input doubles. The cases follow the number of vertex
// indices two mesh triangles share (triangle_intersection.hpp).

#include "triangle_intersection.hpp"

#include <algorithm>
#include <array>

#include "recode/geometry/exact_predicates.hpp"

namespace recode::core::detail {
namespace {

using Point = Eigen::Vector3d;

// A coordinate plane (axes i, j) on which the non-degenerate triangle (a, b, c) projects to a
// non-degenerate triangle, so that projecting points of its plane there keeps every incidence
// (the projection is one-to-one on the plane). One exists: the points are not on one line, so
// some projection of them is not either.
struct Projection {
  int i = 0;
  int j = 1;
};

Projection projectionOf(const Point& a, const Point& b, const Point& c) {
  if (orient2d(a, b, c, 0, 1) != 0) {
    return {0, 1};
  }
  if (orient2d(a, b, c, 1, 2) != 0) {
    return {1, 2};
  }
  return {2, 0};
}

// In the projection: r lies on the closed segment [p, q], given that the three are collinear.
bool onCollinearSegment(const Point& p, const Point& q, const Point& r, Projection axes) {
  for (const int k : {axes.i, axes.j}) {
    if (r[k] < std::min(p[k], q[k]) || r[k] > std::max(p[k], q[k])) {
      return false;
    }
  }
  return true;
}

// In the projection: the closed segments [p, q] and [r, s] (each of two distinct points) meet.
bool segmentsMeet2d(const Point& p, const Point& q, const Point& r, const Point& s,
                    Projection axes) {
  const int o1 = orient2d(p, q, r, axes.i, axes.j);
  const int o2 = orient2d(p, q, s, axes.i, axes.j);
  const int o3 = orient2d(r, s, p, axes.i, axes.j);
  const int o4 = orient2d(r, s, q, axes.i, axes.j);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    return true;  // a proper crossing
  }
  return (o1 == 0 && onCollinearSegment(p, q, r, axes)) ||
         (o2 == 0 && onCollinearSegment(p, q, s, axes)) ||
         (o3 == 0 && onCollinearSegment(r, s, p, axes)) ||
         (o4 == 0 && onCollinearSegment(r, s, q, axes));
}

// In the projection: p lies in the closed triangle (a, b, c), whose projection is
// non-degenerate: no edge sees p on the other side than the triangle's third corner.
bool inTriangle2d(const Point& p, const Point& a, const Point& b, const Point& c, Projection axes) {
  const int turn = orient2d(a, b, c, axes.i, axes.j);
  return orient2d(a, b, p, axes.i, axes.j) != -turn && orient2d(b, c, p, axes.i, axes.j) != -turn &&
         orient2d(c, a, p, axes.i, axes.j) != -turn;
}

// The segment lies in the triangle's plane: it meets the triangle when an end lies in it or
// it crosses or touches an edge.
bool coplanarSegmentMeetsTriangle(const Point& p, const Point& q, const Point& a, const Point& b,
                                  const Point& c) {
  const Projection axes = projectionOf(a, b, c);
  return inTriangle2d(p, a, b, c, axes) || inTriangle2d(q, a, b, c, axes) ||
         segmentsMeet2d(p, q, a, b, axes) || segmentsMeet2d(p, q, b, c, axes) ||
         segmentsMeet2d(p, q, c, a, axes);
}

// The triangle rotated so that vertex index v comes first (v is one of its indices).
Triangle startingAt(const Triangle& t, VertexIndex v) {
  if (t[1] == v) {
    return {t[1], t[2], t[0]};
  }
  if (t[2] == v) {
    return {t[2], t[0], t[1]};
  }
  return t;
}

// The index of t that u does not have (t and u share exactly two).
VertexIndex unsharedOf(const Triangle& t, const Triangle& u) {
  for (const VertexIndex v : t) {
    if (std::find(u.begin(), u.end(), v) == u.end()) {
      return v;
    }
  }
  return t[0];
}

// Two triangles sharing no vertex index meet if and only if an edge of one meets the other:
// their intersection is convex, and an end of it lies on the boundary of one of them (a
// segment across both planes ends where one triangle's boundary crosses the line; in one
// plane, either boundaries cross or one triangle holds the other's corners).
bool disjointTrianglesMeet(const std::array<Point, 3>& t, const std::array<Point, 3>& u) {
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    if (segmentMeetsTriangle(t[k], t[next], u[0], u[1], u[2]) ||
        segmentMeetsTriangle(u[k], u[next], t[0], t[1], t[2])) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool segmentMeetsTriangle(const Point& p, const Point& q, const Point& a, const Point& b,
                          const Point& c) {
  const int sideP = orient3d(a, b, c, p);
  const int sideQ = orient3d(a, b, c, q);
  if (sideP == sideQ && sideP != 0) {
    return false;  // both ends strictly on one side of the plane
  }
  if (sideP == 0 && sideQ == 0) {
    return coplanarSegmentMeetsTriangle(p, q, a, b, c);
  }
  // The segment reaches the plane in one point, that of the line pq; the line passes through
  // the closed triangle when it passes no two edges on opposite sides.
  const int ab = orient3d(p, q, a, b);
  const int bc = orient3d(p, q, b, c);
  const int ca = orient3d(p, q, c, a);
  const bool somePositive = ab > 0 || bc > 0 || ca > 0;
  const bool someNegative = ab < 0 || bc < 0 || ca < 0;
  return !(somePositive && someNegative);
}

int sharedVertexCount(const Triangle& t, const Triangle& u) {
  int shared = 0;
  for (const VertexIndex v : t) {
    shared += std::find(u.begin(), u.end(), v) != u.end() ? 1 : 0;
  }
  return shared;
}

bool trianglesMeet(const TriangleMesh& mesh, const Triangle& t, const Triangle& u) {
  const auto& at = mesh.vertices;
  switch (sharedVertexCount(t, u)) {
    case 0:
      return disjointTrianglesMeet({at[t[0]], at[t[1]], at[t[2]]}, {at[u[0]], at[u[1]], at[u[2]]});
    case 1: {
      // Both contain the shared corner a. Any other common point x makes the segment [a, x]
      // common; followed away from a, it leaves one triangle first, across that triangle's edge
      // opposite a, at a point inside the other. So they meet beyond a exactly when the edge
      // opposite a of one meets the other triangle.
      VertexIndex shared = t[0];
      for (const VertexIndex v : t) {
        if (std::find(u.begin(), u.end(), v) != u.end()) {
          shared = v;
        }
      }
      const Triangle first = startingAt(t, shared);
      const Triangle second = startingAt(u, shared);
      return segmentMeetsTriangle(at[first[1]], at[first[2]], at[second[0]], at[second[1]],
                                  at[second[2]]) ||
             segmentMeetsTriangle(at[second[1]], at[second[2]], at[first[0]], at[first[1]],
                                  at[first[2]]);
    }
    case 2: {
      // Off one plane they meet in their common line, along the shared edge only; in one plane
      // they overlap when their third corners lie on the same side of the shared edge.
      const Triangle edgeFirst = startingAt(t, unsharedOf(t, u));
      const Point& a = at[edgeFirst[1]];
      const Point& b = at[edgeFirst[2]];
      const Point& c = at[edgeFirst[0]];
      const Point& d = at[unsharedOf(u, t)];
      if (orient3d(a, b, c, d) != 0) {
        return false;
      }
      const Projection axes = projectionOf(a, b, c);
      return orient2d(a, b, c, axes.i, axes.j) == orient2d(a, b, d, axes.i, axes.j);
    }
    default:
      return true;  // the same three vertices: the same triangle, twice
  }
}

}  // namespace recode::core::detail
