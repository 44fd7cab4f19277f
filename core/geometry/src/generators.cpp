#include "recode/geometry/generators.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "format.hpp"

namespace recode::core {
namespace {

using detail::formatDouble;

void requirePositive(const char* function, const char* name, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw std::invalid_argument(std::string(function) + ": " + name +
                                " must be finite and > 0, got " + formatDouble(value));
  }
}

void requireAtLeast(const char* function, const char* name, int value, int minimum) {
  if (value < minimum) {
    throw std::invalid_argument(std::string(function) + ": " + name + " must be at least " +
                                std::to_string(minimum) + ", got " + std::to_string(value));
  }
}

// Rejects tessellations with more than kMaxGeneratedTriangles triangles. `triangles` is
// computed in double precision by the caller so that it cannot overflow; `parameters`
// describes the tessellation parameters for the message.
void requireTriangleBudget(const char* function, const std::string& parameters, double triangles) {
  if (triangles > static_cast<double>(kMaxGeneratedTriangles)) {
    throw std::invalid_argument(std::string(function) + ": " + parameters + " would make " +
                                formatDouble(triangles) + " triangles, more than the limit of " +
                                std::to_string(kMaxGeneratedTriangles));
  }
}

// A point of a meridian profile: distance from the z axis and height.
struct ProfilePoint {
  double rho;
  double z;
};

// Surface of revolution around z. `profile` runs from bottom to top; its first and last
// points are on the axis (rho = 0: single vertices), the others are rings of `segments`
// vertices. x and y of ring vertices are scaled by sx and sy (for the ellipsoid).
TriangleMesh revolve(const std::vector<ProfilePoint>& profile, int segments, double sx = 1.0,
                     double sy = 1.0) {
  const auto s = static_cast<VertexIndex>(segments);
  const auto rings = static_cast<VertexIndex>(profile.size() - 2);

  std::vector<double> cosines(s);
  std::vector<double> sines(s);
  for (VertexIndex j = 0; j < s; ++j) {
    const double theta = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(s);
    cosines[j] = std::cos(theta);
    sines[j] = std::sin(theta);
  }

  TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(rings) * s + 2);
  mesh.triangles.reserve(2 * static_cast<std::size_t>(rings) * s);

  mesh.vertices.emplace_back(0.0, 0.0, profile.front().z);
  for (VertexIndex r = 0; r < rings; ++r) {
    const ProfilePoint& p = profile[r + 1];
    for (VertexIndex j = 0; j < s; ++j) {
      mesh.vertices.emplace_back(sx * p.rho * cosines[j], sy * p.rho * sines[j], p.z);
    }
  }
  mesh.vertices.emplace_back(0.0, 0.0, profile.back().z);

  const VertexIndex bottom = 0;
  const VertexIndex top = rings * s + 1;
  auto ring = [s](VertexIndex r, VertexIndex j) { return 1 + r * s + (j % s); };

  for (VertexIndex j = 0; j < s; ++j) {
    mesh.triangles.push_back({bottom, ring(0, j + 1), ring(0, j)});
  }
  for (VertexIndex r = 0; r + 1 < rings; ++r) {
    for (VertexIndex j = 0; j < s; ++j) {
      mesh.triangles.push_back({ring(r, j), ring(r, j + 1), ring(r + 1, j + 1)});
      mesh.triangles.push_back({ring(r, j), ring(r + 1, j + 1), ring(r + 1, j)});
    }
  }
  for (VertexIndex j = 0; j < s; ++j) {
    mesh.triangles.push_back({ring(rings - 1, j), ring(rings - 1, j + 1), top});
  }
  return mesh;
}

// Latitudes -pi/2 < psi_k < pi/2, k = 1 .. rings - 1, of a sphere divided into `rings`
// bands equally spaced in latitude; computed as pi * (2k - rings) / (2 rings) so that the
// list is symmetric about 0.
double sphereLatitude(int k, int rings) {
  return std::numbers::pi * static_cast<double>(2 * k - rings) / static_cast<double>(2 * rings);
}

}  // namespace

TriangleMesh makeCone(double radius, double height, int segments) {
  constexpr const char* kFunction = "makeCone";
  requirePositive(kFunction, "radius", radius);
  requirePositive(kFunction, "height", height);
  requireAtLeast(kFunction, "segments", segments, 3);
  requireTriangleBudget(kFunction, "segments = " + std::to_string(segments),
                        2.0 * static_cast<double>(segments));
  return revolve({{0.0, 0.0}, {radius, 0.0}, {0.0, height}}, segments);
}

TriangleMesh makeCylinder(double radius, double height, int segments) {
  constexpr const char* kFunction = "makeCylinder";
  requirePositive(kFunction, "radius", radius);
  requirePositive(kFunction, "height", height);
  requireAtLeast(kFunction, "segments", segments, 3);
  requireTriangleBudget(kFunction, "segments = " + std::to_string(segments),
                        4.0 * static_cast<double>(segments));
  return revolve({{0.0, 0.0}, {radius, 0.0}, {radius, height}, {0.0, height}}, segments);
}

TriangleMesh makeCappedCone(double r0, double r1, double height, int segments, int rings) {
  constexpr const char* kFunction = "makeCappedCone";
  requirePositive(kFunction, "r0", r0);
  requirePositive(kFunction, "r1", r1);
  requirePositive(kFunction, "height", height);
  requireAtLeast(kFunction, "segments", segments, 3);
  requireAtLeast(kFunction, "rings", rings, 1);
  if (!(height > std::abs(r0 - r1))) {
    throw std::invalid_argument(std::string(kFunction) + ": height must exceed |r0 - r1| = " +
                                formatDouble(std::abs(r0 - r1)) + " (otherwise one cap sphere " +
                                "contains the other), got " + formatDouble(height));
  }
  requireTriangleBudget(
      kFunction, "segments = " + std::to_string(segments) + " and rings = " + std::to_string(rings),
      4.0 * static_cast<double>(rings) * static_cast<double>(segments));

  // Latitude of the two tangent circles: the outward normal of the lateral surface makes
  // the angle phi with the xy plane, sin(phi) = (r0 - r1) / height.
  const double phi = std::asin((r0 - r1) / height);
  const double halfPi = std::numbers::pi / 2.0;

  std::vector<ProfilePoint> profile;
  profile.reserve(2 * static_cast<std::size_t>(rings) + 2);
  profile.push_back({0.0, -r0});
  for (int k = 1; k <= rings; ++k) {  // bottom cap, k = rings is the tangent circle
    const double psi = -halfPi + (phi + halfPi) * static_cast<double>(k) / rings;
    profile.push_back({r0 * std::cos(psi), r0 * std::sin(psi)});
  }
  for (int k = 0; k < rings; ++k) {  // top cap, k = 0 is the tangent circle
    const double psi = phi + (halfPi - phi) * static_cast<double>(k) / rings;
    profile.push_back({r1 * std::cos(psi), height + r1 * std::sin(psi)});
  }
  profile.push_back({0.0, height + r1});
  return revolve(profile, segments);
}

TriangleMesh makeEllipsoid(double a, double b, double c, int segments, int rings) {
  constexpr const char* kFunction = "makeEllipsoid";
  requirePositive(kFunction, "a", a);
  requirePositive(kFunction, "b", b);
  requirePositive(kFunction, "c", c);
  requireAtLeast(kFunction, "segments", segments, 3);
  requireAtLeast(kFunction, "rings", rings, 2);
  requireTriangleBudget(
      kFunction, "segments = " + std::to_string(segments) + " and rings = " + std::to_string(rings),
      2.0 * (static_cast<double>(rings) - 1.0) * static_cast<double>(segments));

  std::vector<ProfilePoint> profile;
  profile.reserve(static_cast<std::size_t>(rings) + 1);
  profile.push_back({0.0, -c});
  for (int k = 1; k < rings; ++k) {
    const double psi = sphereLatitude(k, rings);
    profile.push_back({std::cos(psi), c * std::sin(psi)});
  }
  profile.push_back({0.0, c});
  return revolve(profile, segments, a, b);
}

TriangleMesh makeSphere(double radius, int segments, int rings) {
  constexpr const char* kFunction = "makeSphere";
  requirePositive(kFunction, "radius", radius);
  requireAtLeast(kFunction, "segments", segments, 3);
  requireAtLeast(kFunction, "rings", rings, 2);
  requireTriangleBudget(
      kFunction, "segments = " + std::to_string(segments) + " and rings = " + std::to_string(rings),
      2.0 * (static_cast<double>(rings) - 1.0) * static_cast<double>(segments));
  return makeEllipsoid(radius, radius, radius, segments, rings);
}

TriangleMesh makeTorus(double radius, double tubeRadius, int segments, int rings) {
  constexpr const char* kFunction = "makeTorus";
  requirePositive(kFunction, "radius", radius);
  requirePositive(kFunction, "tubeRadius", tubeRadius);
  if (!(tubeRadius < radius)) {
    throw std::invalid_argument(std::string(kFunction) + ": tubeRadius must be below radius (" +
                                formatDouble(radius) + ") so that the hole stays open, got " +
                                formatDouble(tubeRadius));
  }
  requireAtLeast(kFunction, "segments", segments, 3);
  requireAtLeast(kFunction, "rings", rings, 3);
  requireTriangleBudget(
      kFunction, "segments = " + std::to_string(segments) + " and rings = " + std::to_string(rings),
      2.0 * static_cast<double>(segments) * static_cast<double>(rings));
  TriangleMesh m;
  m.vertices.reserve(static_cast<std::size_t>(segments) * static_cast<std::size_t>(rings));
  for (int i = 0; i < segments; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / segments;
    for (int j = 0; j < rings; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / rings;
      const double w = radius + tubeRadius * std::cos(theta);
      m.vertices.emplace_back(w * std::cos(phi), w * std::sin(phi), tubeRadius * std::sin(theta));
    }
  }
  const auto at = [&](int i, int j) {
    return static_cast<VertexIndex>((i % segments) * rings + (j % rings));
  };
  m.triangles.reserve(2 * m.vertices.size());
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < rings; ++j) {
      // The azimuth's direction (i) crossed with the tube angle's (j) points out of the tube.
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

TriangleMesh makeBox(double hx, double hy, double hz) {
  constexpr const char* kFunction = "makeBox";
  requirePositive(kFunction, "hx", hx);
  requirePositive(kFunction, "hy", hy);
  requirePositive(kFunction, "hz", hz);

  TriangleMesh mesh;
  mesh.vertices.reserve(8);
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) != 0 ? hx : -hx, (i & 2) != 0 ? hy : -hy,
                               (i & 4) != 0 ? hz : -hz);
  }
  mesh.triangles = {
      {0, 4, 6}, {0, 6, 2},  // -x
      {1, 3, 7}, {1, 7, 5},  // +x
      {0, 1, 5}, {0, 5, 4},  // -y
      {2, 6, 7}, {2, 7, 3},  // +y
      {0, 2, 3}, {0, 3, 1},  // -z
      {4, 5, 7}, {4, 7, 6},  // +z
  };
  return mesh;
}

TriangleMesh makeBox(const Eigen::Vector3d& halfExtents) {
  return makeBox(halfExtents.x(), halfExtents.y(), halfExtents.z());
}

}  // namespace recode::core
