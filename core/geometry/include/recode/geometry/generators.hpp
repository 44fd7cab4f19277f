#pragma once
// Tessellated primitive solids, each (but the torus, at the end) a closed convex TriangleMesh
// that passes validateConvexBlock: vertices are shared (no duplicates; every pole, apex and cap
// centre is one vertex), faces are counter-clockwise seen from outside.
//
// Round solids are built from rings of `segments` vertices around the z axis. Ring vertex
// j (0 <= j < segments) lies at azimuth 2*pi*j/segments measured from +x toward +y.
// Vertex order is bottom to top: the bottom pole (or base centre) is vertex 0, then each
// ring in order of increasing z, then the top pole (or apex, or top centre) last. With
// m rings the counts are V = m * segments + 2 and F = 2 * m * segments.
//
// Invalid parameters throw std::invalid_argument whose message names the parameter and
// its value: sizes must be finite and > 0, segments >= 3, rings >= the minimum given below,
// and the triangle count may not exceed kMaxGeneratedTriangles.
//
// docs/geometry.md has the same conventions and the volume formulas.

#include <cstddef>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// Upper bound on the number of triangles one generator call may produce (2^25, under 1 GiB
// of triangles and vertices); larger requests are rejected instead of exhausting memory.
inline constexpr std::size_t kMaxGeneratedTriangles = std::size_t{1} << 25;

// Cone: base disc of `radius` centred at the origin in the z = 0 plane, apex at
// (0, 0, height). One ring (the base rim) plus base centre and apex:
// V = segments + 2, F = 2 * segments.
[[nodiscard]] TriangleMesh makeCone(double radius, double height, int segments);

// Cylinder: axis along z, bottom disc centred at the origin in z = 0, top disc centred at
// (0, 0, height). Two rings plus the two disc centres: V = 2 * segments + 2,
// F = 4 * segments.
[[nodiscard]] TriangleMesh makeCylinder(double radius, double height, int segments);

// Capped cone (the paper's "truncated cone with spherical caps"): the convex hull of a
// sphere of radius r0 centred at the origin and a sphere of radius r1 centred at
// (0, 0, height). The lateral surface is the cone tangent to both spheres; each sphere
// contributes the cap beyond its tangent circle. The solid spans z in [-r0, height + r1].
// Requires height > |r0 - r1| (otherwise one sphere contains the other). Each cap is
// divided into `rings` latitude bands (rings >= 1); the tangent circles are rings shared
// with the lateral band, so there are 2 * rings rings: V = 2 * rings * segments + 2,
// F = 4 * rings * segments.
[[nodiscard]] TriangleMesh makeCappedCone(double r0, double r1, double height, int segments,
                                          int rings);

// Ellipsoid centred at the origin with semi-axes a, b, c along x, y, z. `rings` is the number
// of latitude bands between the poles (0, 0, -c) and (0, 0, c) (rings >= 2), equally spaced
// in the polar angle; there are rings - 1 rings: V = (rings - 1) * segments + 2,
// F = 2 * (rings - 1) * segments.
[[nodiscard]] TriangleMesh makeEllipsoid(double a, double b, double c, int segments, int rings);

// Sphere of `radius` centred at the origin: makeEllipsoid(radius, radius, radius, ...).
[[nodiscard]] TriangleMesh makeSphere(double radius, int segments, int rings);

// Axis-aligned box centred at the origin with half extents hx, hy, hz: 8 vertices, 12
// triangles (two per side). Vertex i is (±hx, ±hy, ±hz) with the sign of x taken from
// bit 0 of i, y from bit 1 and z from bit 2 (set bit: +).
[[nodiscard]] TriangleMesh makeBox(double hx, double hy, double hz);
[[nodiscard]] TriangleMesh makeBox(const Eigen::Vector3d& halfExtents);

// Not convex: a closed mesh for the layered pair (layered_pair.hpp), which validateConvexBlock
// refuses and core::validateClosedMesh accepts.
//
// Torus about the z axis through the origin: the tube's centre circle has `radius` in the
// z = 0 plane, the tube `tubeRadius` (0 < tubeRadius < radius, so the hole stays open).
// `segments` rings of vertices around the z axis (segments >= 3), each of `rings` vertices
// around the tube (rings >= 3); vertex (i, j) is index i * rings + j, at azimuth 2*pi*i/segments
// and tube angle 2*pi*j/rings measured from the outside of the tube toward +z:
// V = segments * rings, F = 2 * segments * rings.
[[nodiscard]] TriangleMesh makeTorus(double radius, double tubeRadius, int segments, int rings);

}  // namespace recode::core
