// The generated pair suite: see pair_suite.hpp. Every random number comes from one
// std::mt19937 drawn through our own mapping to [0, 1) (the standard distributions' outputs are
// implementation-defined), so the suite is the same on every compiler and library.

#include "recode/verify/pair_suite.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

#include "recode/geometry/generators.hpp"
#include "suite_support.hpp"

namespace recode::verify {

namespace {

using Eigen::Vector3d;

// Gaps (world units; the blocks are about one unit across) used by the touching
// configurations, in turn: clear overlap, slight overlap, overlap under one depth step, exact
// touching, a gap under one depth step, a slight gap, a clear gap. One depth step of the
// suite's frames is a few 1e-7 world units, so ±1e-7 sits inside the rounding.
constexpr std::array<double, 7> kGaps = {-0.05, -1e-3, -1e-7, 0.0, 1e-7, 1e-3, 0.05};

// An octahedron with semi-axes a, b, c: vertices on the axes, faces counter-clockwise seen
// from outside.
core::TriangleMesh makeOctahedron(double a, double b, double c) {
  core::TriangleMesh m;
  m.vertices = {{-a, 0, 0}, {a, 0, 0}, {0, -b, 0}, {0, b, 0}, {0, 0, -c}, {0, 0, c}};
  // For every octant (signs sx, sy, sz) one face through the three axis vertices there,
  // ordered x, y, z when the octant's orientation is positive, else x, z, y.
  for (int octant = 0; octant < 8; ++octant) {
    const bool px = octant & 1, py = octant & 2, pz = octant & 4;
    const core::VertexIndex vx = px ? 1 : 0, vy = py ? 3 : 2, vz = pz ? 5 : 4;
    const bool positive = (px == py) == pz;  // sx * sy * sz > 0
    if (positive)
      m.triangles.push_back({vx, vy, vz});
    else
      m.triangles.push_back({vx, vz, vy});
  }
  return m;
}

enum class Shape { Cone, Needle, Box, Ellipsoid, CappedCone, Octahedron };
constexpr std::array<const char*, 6> kShapeNames = {"cone",      "needle",      "box",
                                                    "ellipsoid", "capped-cone", "octahedron"};

struct Block {
  core::TriangleMesh mesh;  // local coordinates
  Shape shape = Shape::Box;
};

Block makeShape(Shape shape, Random& rnd) {
  switch (shape) {
    case Shape::Cone:
      return {core::makeCone(rnd.uniform(0.4, 1.0), rnd.uniform(1.0, 2.0), 8 + 8 * rnd.index(3)),
              shape};
    case Shape::Needle:
      return {core::makeCone(rnd.uniform(0.03, 0.08), rnd.uniform(1.5, 2.5), 12), shape};
    case Shape::Box:
      return {core::makeBox(rnd.uniform(0.2, 1.0), rnd.uniform(0.2, 1.0), rnd.uniform(0.2, 1.0)),
              shape};
    case Shape::Ellipsoid:
      return {core::makeEllipsoid(rnd.uniform(0.3, 1.0), rnd.uniform(0.3, 1.0),
                                  rnd.uniform(0.1, 1.0), 16, 8),
              shape};
    case Shape::CappedCone:
      return {core::makeCappedCone(rnd.uniform(0.3, 0.6), rnd.uniform(0.1, 0.3),
                                   rnd.uniform(0.8, 1.5), 16, 3),
              shape};
    case Shape::Octahedron:
      return {makeOctahedron(rnd.uniform(0.3, 1.0), rnd.uniform(0.3, 1.0), rnd.uniform(0.3, 1.0)),
              shape};
  }
  throw std::logic_error("makeShape: unknown shape");
}

Block randomShape(Random& rnd) {
  return makeShape(static_cast<Shape>(rnd.index(6)), rnd);
}

double boundingRadius(const core::TriangleMesh& m) {
  double r = 0.0;
  for (const Vector3d& v : m.vertices)
    r = std::max(r, v.norm());
  return r;
}

// A pointed block (cone or needle) with its apex moved to the local origin and its body
// below it (local z < 0).
Block pointedAtOrigin(Random& rnd) {
  Block b = makeShape(rnd.index(2) == 0 ? Shape::Cone : Shape::Needle, rnd);
  const double apexZ = b.mesh.vertices.back().z();  // the apex is the last vertex
  b.mesh = core::transformed(b.mesh, pose(Eigen::Matrix3d::Identity(), Vector3d(0, 0, -apexZ)));
  return b;
}

// A rotation taking +z to `d` (unit).
Eigen::Matrix3d rotationTakingZTo(const Vector3d& d) {
  return Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), d).toRotationMatrix();
}

// Whole-pair placement: exact quarter turns on even indices (so exact touching stays exact),
// a random rotation on odd ones; a random translation on both.
Eigen::Isometry3d worldPlacement(int index, Random& rnd) {
  const Eigen::Matrix3d r = index % 2 == 0 ? rnd.quarterTurns() : rnd.rotation();
  const Vector3d t(std::round(rnd.uniform(-4, 4)), std::round(rnd.uniform(-4, 4)),
                   std::round(rnd.uniform(-4, 4)));
  return pose(r, t);
}

struct Generated {
  Block a, b;
};

Generated randomPair(Random& rnd) {
  Generated g{randomShape(rnd), randomShape(rnd)};
  g.a.mesh = core::transformed(g.a.mesh, pose(rnd.rotation(), Vector3d::Zero()));
  const double reach = boundingRadius(g.a.mesh) + boundingRadius(g.b.mesh);
  g.b.mesh = core::transformed(
      g.b.mesh, pose(rnd.rotation(), rnd.direction() * rnd.uniform(0.0, 1.1) * reach));
  return g;
}

Generated tipOnTip(int k, Random& rnd) {
  Generated g{pointedAtOrigin(rnd), pointedAtOrigin(rnd)};
  // A points up (+z, body below); B points down at it, tilted by up to 30 degrees, with its
  // apex `gap` above A's.
  const double tilt = rnd.uniform(0.0, M_PI / 6.0), azimuth = rnd.uniform(0.0, 2.0 * M_PI);
  const Vector3d down(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
                      -std::cos(tilt));
  g.b.mesh = core::transformed(g.b.mesh, pose(rotationTakingZTo(down), Vector3d(0, 0, kGaps[k])));
  return g;
}

Generated tipOnFace(int k, Random& rnd) {
  Generated g{makeShape(rnd.index(2) == 0 ? Shape::Box : Shape::Octahedron, rnd),
              pointedAtOrigin(rnd)};
  // A point on a face of A and that face's outward normal, both in A's local frame.
  Vector3d point, normal;
  const auto& v = g.a.mesh.vertices;
  if (g.a.shape == Shape::Box) {
    const Vector3d half = v[7];  // (+hx, +hy, +hz)
    point =
        Vector3d(rnd.uniform(-0.6, 0.6) * half.x(), rnd.uniform(-0.6, 0.6) * half.y(), half.z());
    normal = Vector3d::UnitZ();
  } else {
    const Vector3d px = v[1], py = v[3], pz = v[5];  // the face in the + octant
    double u = rnd.uniform(0.1, 0.8), w = rnd.uniform(0.1, 0.8);
    if (u + w > 0.9) {
      u *= 0.5;
      w *= 0.5;
    }
    point = px + u * (py - px) + w * (pz - px);
    normal = (py - px).cross(pz - px).normalized();
  }
  // B's apex at the point plus `gap` along the normal, pointing into the face, tilted.
  const double tilt = rnd.uniform(0.0, M_PI / 4.0), azimuth = rnd.uniform(0.0, 2.0 * M_PI);
  const Eigen::Matrix3d toNormal = rotationTakingZTo(-normal);
  const Vector3d into = toNormal * Vector3d(std::sin(tilt) * std::cos(azimuth),
                                            std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
  g.b.mesh = core::transformed(g.b.mesh, pose(rotationTakingZTo(into), point + kGaps[k] * normal));
  return g;
}

Generated faceOnFace(int k, Random& rnd) {
  Generated g{makeShape(Shape::Box, rnd), makeShape(Shape::Box, rnd)};
  const double topA = g.a.mesh.vertices[7].z(), bottomB = g.b.mesh.vertices[7].z();
  // B sits on A's top face, turned about z by a quarter turn or a random angle, shifted.
  const double turn = rnd.index(2) == 0 ? 0.0 : rnd.uniform(0.0, M_PI);
  const Vector3d shift(rnd.uniform(-0.5, 0.5) * g.a.mesh.vertices[7].x(),
                       rnd.uniform(-0.5, 0.5) * g.a.mesh.vertices[7].y(), topA + bottomB);
  g.b.mesh = core::transformed(g.b.mesh,
                               pose(Eigen::AngleAxisd(turn, Vector3d::UnitZ()).toRotationMatrix(),
                                    shift + Vector3d(0, 0, kGaps[k])));
  return g;
}

Generated edgeOnEdge(int k, Random& rnd) {
  // A: a box turned 45 degrees about x, so its top is an edge along x. B: a box turned 45
  // degrees about y, so its bottom is an edge along y, crossing A's above it.
  const double s = rnd.uniform(0.3, 0.8), t = rnd.uniform(0.3, 0.8);
  Generated g{{core::makeBox(rnd.uniform(0.5, 1.0), s, s), Shape::Box},
              {core::makeBox(t, rnd.uniform(0.5, 1.0), t), Shape::Box}};
  const Eigen::Matrix3d aboutX =
      Eigen::AngleAxisd(M_PI / 4.0, Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d aboutY =
      Eigen::AngleAxisd(M_PI / 4.0, Vector3d::UnitY()).toRotationMatrix();
  g.a.mesh = core::transformed(g.a.mesh, pose(aboutX, Vector3d::Zero()));
  const double topA = s * std::sqrt(2.0), bottomB = t * std::sqrt(2.0);
  g.b.mesh = core::transformed(g.b.mesh,
                               pose(aboutY, Vector3d(rnd.uniform(-0.3, 0.3), rnd.uniform(-0.3, 0.3),
                                                     topA + bottomB + kGaps[k])));
  return g;
}

Generated inside(Random& rnd) {
  // The outer block's inscribed ball has radius at least ~0.6 for these sizes.
  Block outer = rnd.index(2) == 0
                    ? Block{core::makeBox(rnd.uniform(0.8, 1.2), rnd.uniform(0.8, 1.2),
                                          rnd.uniform(0.8, 1.2)),
                            Shape::Box}
                    : Block{core::makeEllipsoid(rnd.uniform(0.9, 1.2), rnd.uniform(0.9, 1.2),
                                                rnd.uniform(0.9, 1.2), 16, 8),
                            Shape::Ellipsoid};
  Block inner = randomShape(rnd);
  // Shrink the inner block into a ball of radius 0.25 and place it within 0.3 of the centre.
  const double scale = 0.25 / boundingRadius(inner.mesh);
  Eigen::Affine3d shrink = Eigen::Affine3d::Identity();
  shrink.linear() = scale * rnd.rotation();
  shrink.translation() = rnd.direction() * rnd.uniform(0.0, 0.3);
  inner.mesh = core::transformed(inner.mesh, shrink);
  return rnd.index(2) == 0 ? Generated{outer, inner} : Generated{inner, outer};
}

Generated justSeparated(int k, Random& rnd) {
  Generated g = randomPair(rnd);
  const Vector3d d = rnd.direction();
  double maxA = -INFINITY, minB = INFINITY;
  for (const Vector3d& p : g.a.mesh.vertices)
    maxA = std::max(maxA, d.dot(p));
  for (const Vector3d& p : g.b.mesh.vertices)
    minB = std::min(minB, d.dot(p));
  static constexpr std::array<double, 4> kSeparations = {1e-6, 1e-4, 1e-3, 1e-2};
  const double shift = maxA - minB + kSeparations[static_cast<std::size_t>(k) % 4];
  g.b.mesh = core::transformed(g.b.mesh, pose(Eigen::Matrix3d::Identity(), shift * d));
  return g;
}

// Rejected up front, naming the option, so that a bad request never yields a partial suite.
void requireValidOptions(const PairSuiteOptions& options) {
  if (options.count < 1)
    throw std::invalid_argument("generatePairSuite: count must be at least 1, got " +
                                std::to_string(options.count));
  if (options.width < 1 || options.width > 4096)
    throw std::invalid_argument("generatePairSuite: width must be in 1..4096, got " +
                                std::to_string(options.width));
}

// The view axes, taken in turn by successive pairs so that every configuration is seen along
// each of them.
constexpr std::array<core::ViewAxis, 3> kAxes = {core::ViewAxis::X, core::ViewAxis::Y,
                                                 core::ViewAxis::Z};

// The blocks, in local coordinates, of the `round`-th pair of `configuration`; the touching
// configurations step through kGaps round by round.
Generated generateConfiguration(PairConfiguration configuration, int round, Random& rnd) {
  const int gap = round % static_cast<int>(kGaps.size());
  switch (configuration) {
    case PairConfiguration::Random:
      return randomPair(rnd);
    case PairConfiguration::TipOnTip:
      return tipOnTip(gap, rnd);
    case PairConfiguration::TipOnFace:
      return tipOnFace(gap, rnd);
    case PairConfiguration::FaceOnFace:
      return faceOnFace(gap, rnd);
    case PairConfiguration::EdgeOnEdge:
      return edgeOnEdge(gap, rnd);
    case PairConfiguration::Inside:
      return inside(rnd);
    case PairConfiguration::JustSeparated:
      return justSeparated(round, rnd);
  }
  return {};
}

// The pair's name in reports: configuration/round, the two shapes and the view axis, which
// together make it unique within a suite.
std::string pairLabel(PairConfiguration configuration, int round, const Generated& g,
                      core::ViewAxis axis) {
  char label[96];
  std::snprintf(
      label, sizeof label, "%s/%03d %s-%s %s", std::string(toString(configuration)).c_str(), round,
      kShapeNames[static_cast<std::size_t>(g.a.shape)],
      kShapeNames[static_cast<std::size_t>(g.b.shape)], std::string(core::toString(axis)).c_str());
  return label;
}

// Moves both blocks by the pair's world placement (drawn after the blocks, so the suite's
// random sequence is fixed) and frames them along `axis` at `width` pixels.
SuitePair placePair(PairConfiguration configuration, int round, const Generated& g,
                    core::ViewAxis axis, int width, Random& rnd) {
  const Eigen::Isometry3d world = worldPlacement(round, rnd);
  SuitePair pair;
  pair.configuration = configuration;
  pair.a = core::transformed(g.a.mesh, world);
  pair.b = core::transformed(g.b.mesh, world);
  core::Aabb bounds = core::boundingBox(pair.a);
  bounds.extend(core::boundingBox(pair.b));
  core::ViewSpec view;
  view.axis = axis;
  core::FrameOverrides overrides;
  overrides.width = width;
  pair.frame = core::resolveFrame(view, bounds, overrides);
  pair.label = pairLabel(configuration, round, g, axis);
  return pair;
}

}  // namespace

std::string_view toString(PairConfiguration configuration) {
  switch (configuration) {
    case PairConfiguration::Random:
      return "random";
    case PairConfiguration::TipOnTip:
      return "tip-on-tip";
    case PairConfiguration::TipOnFace:
      return "tip-on-face";
    case PairConfiguration::FaceOnFace:
      return "face-on-face";
    case PairConfiguration::EdgeOnEdge:
      return "edge-on-edge";
    case PairConfiguration::Inside:
      return "inside";
    case PairConfiguration::JustSeparated:
      return "just-separated";
  }
  return "unknown";
}

std::vector<SuitePair> generatePairSuite(const PairSuiteOptions& options) {
  requireValidOptions(options);
  Random rnd(options.seed);
  std::vector<SuitePair> suite;
  suite.reserve(static_cast<std::size_t>(options.count));
  for (int i = 0; i < options.count; ++i) {
    const auto configuration = static_cast<PairConfiguration>(i % kPairConfigurationCount);
    const int round = i / kPairConfigurationCount;  // how many of this configuration so far
    const Generated g = generateConfiguration(configuration, round, rnd);
    const core::ViewAxis axis = kAxes[static_cast<std::size_t>(i) % kAxes.size()];
    suite.push_back(placePair(configuration, round, g, axis, options.width, rnd));
  }
  return suite;
}

}  // namespace recode::verify
