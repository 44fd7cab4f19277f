// The mode property suite: see mode_properties.hpp.

#include "recode/verify/mode_properties.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "suite_support.hpp"

namespace recode::verify {

namespace {

using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

// Two blocks in local coordinates, B to be set on top of A (along +z) with its lowest point over
// A's top at the lateral offset; `feature` is the size of the smaller contact feature, which
// scales the gaps.
struct Stack {
  const char* name;
  core::TriangleMesh a;
  core::TriangleMesh b;
  Eigen::Vector2d offset;
  double feature;
};

Eigen::Vector2d lateral(Random& rnd, double reach) {
  return {rnd.uniform(-reach, reach), rnd.uniform(-reach, reach)};
}

core::TriangleMesh turned(const core::TriangleMesh& m, const Eigen::Matrix3d& r) {
  return core::transformed(m, pose(r, Vector3d::Zero()));
}

Eigen::Matrix3d about(int axis, double radians) {
  return Eigen::AngleAxisd(radians, Vector3d::Unit(axis)).toRotationMatrix();
}

// A capsule lying along x: a capped cone with equal radii turned a quarter about y.
core::TriangleMesh lyingCapsule(double radius, double length) {
  return turned(core::makeCappedCone(radius, radius, length, 16, 3), about(1, kPi / 2));
}

Stack makeStack(int configuration, Random& rnd) {
  switch (configuration) {
    case 0: {  // a large sphere's pole on a thin post's top face
      const double r = rnd.uniform(0.01, 0.05);
      return {"sphere-on-post",
              core::makeCylinder(r, rnd.uniform(0.05, 0.2), 16 + 8 * rnd.index(3)),
              core::makeSphere(rnd.uniform(2.0, 12.0), 32, 16), lateral(rnd, 0.7 * r), r};
    }
    case 1: {  // a small ball on a wide flat disk
      const double radius = rnd.uniform(3.0, 10.0);
      const double ball = rnd.uniform(0.05, 1.0);
      return {"ball-on-disk", core::makeCylinder(radius, rnd.uniform(0.001, 0.005), 32),
              core::makeSphere(ball, 24, 12), lateral(rnd, 0.6 * radius), ball};
    }
    case 2: {  // boxes face to face, plates among them
      const Vector3d ha(rnd.uniform(0.05, 1.0), rnd.uniform(0.05, 1.0), rnd.uniform(0.002, 0.5));
      const Vector3d hb(rnd.uniform(0.05, 1.0), rnd.uniform(0.05, 1.0), rnd.uniform(0.002, 0.5));
      const double smaller = std::min(ha.head<2>().minCoeff(), hb.head<2>().minCoeff());
      return {"box-face-face", core::makeBox(ha), core::makeBox(hb), lateral(rnd, smaller),
              smaller};
    }
    case 3: {  // boxes edge to edge: A's top edge along x, B's bottom edge along y
      const Vector3d ha(rnd.uniform(0.1, 1.0), rnd.uniform(0.05, 0.5), rnd.uniform(0.05, 0.5));
      const Vector3d hb(rnd.uniform(0.05, 0.5), rnd.uniform(0.1, 1.0), rnd.uniform(0.05, 0.5));
      return {"box-edge-edge", turned(core::makeBox(ha), about(0, kPi / 4)),
              turned(core::makeBox(hb), about(1, kPi / 4)), lateral(rnd, 0.05),
              std::min(ha.minCoeff(), hb.minCoeff())};
    }
    case 4: {  // capsules crossed, or a capsule on a box
      const double r = rnd.uniform(0.02, 0.5);
      const core::TriangleMesh upper =
          turned(lyingCapsule(r, rnd.uniform(0.5, 2.0)), about(2, rnd.uniform(0.0, kPi)));
      const core::TriangleMesh lower =
          rnd.index(2) == 0
              ? lyingCapsule(rnd.uniform(0.02, 0.5), rnd.uniform(0.5, 2.0))
              : core::makeBox(rnd.uniform(0.5, 2.0), rnd.uniform(0.5, 2.0), rnd.uniform(0.01, 0.5));
      return {"capsules", lower, upper, lateral(rnd, 0.3 * r), r};
    }
    default: {  // a cone's tip down on a flat disk
      const double radius = rnd.uniform(1.0, 6.0);
      const double cone = rnd.uniform(0.02, 0.5);
      return {
          "cone-tip-on-disk", core::makeCylinder(radius, rnd.uniform(0.001, 0.01), 32),
          turned(core::makeCone(cone, rnd.uniform(0.5, 2.0), 8 + 8 * rnd.index(3)), about(0, kPi)),
          lateral(rnd, 0.6 * radius), cone};
    }
  }
}

// A small turn: 10^u degrees, u uniform in [-9, 1], about x, y, z or a random direction.
struct Turn {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double degrees = 0.0;
  char axis = '-';  // 'x', 'y', 'z', 'r' (random direction) or '-' (none)
};

Turn smallTurn(Random& rnd) {
  Turn t;
  t.degrees = std::pow(10.0, rnd.uniform(-9.0, 1.0)) * (rnd.index(2) == 0 ? 1.0 : -1.0);
  const int k = rnd.index(4);
  const Vector3d axis = k < 3 ? Vector3d::Unit(k) : rnd.direction();
  t.axis = "xyzr"[k];
  t.rotation = Eigen::AngleAxisd(t.degrees * kPi / 180.0, axis).toRotationMatrix();
  return t;
}

// A block turned about `pivot`.
core::TriangleMesh turnedAbout(const core::TriangleMesh& m, const Turn& turn,
                               const Vector3d& pivot) {
  return core::transformed(m, pose(turn.rotation, pivot - turn.rotation * pivot));
}

// The gap along z between A's top and B's lowest point before the turns: touching exactly, or
// +- 10^u times the feature size, u uniform in [-12, -1].
double drawGap(Random& rnd, double feature) {
  const int kind = rnd.index(5);
  if (kind == 0)
    return 0.0;
  return (kind <= 2 ? -1.0 : 1.0) * feature * std::pow(10.0, rnd.uniform(-12.0, -1.0));
}

std::string caseLabel(const char* name, long long index, const Turn& ta, const Turn& tb, double gap,
                      core::ViewAxis axis, int width) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%s/%06lld A %.2g deg about %c, B %.2g deg about %c, gap %.2g, %s %d", name, index,
                ta.degrees, ta.axis, tb.degrees, tb.axis, gap,
                axis == core::ViewAxis::X   ? "x"
                : axis == core::ViewAxis::Y ? "y"
                                            : "z",
                width);
  return buf;
}

void fail(PropertyTally& tally, const PropertyCase& c, const char* what) {
  if (tally.failures.size() < 20)
    tally.failures.push_back(c.label + ": " + what);
}

}  // namespace

PropertyCase propertyCase(long long index, std::uint32_t seed) {
  if (index < 0)
    throw std::invalid_argument("propertyCase: the index must be >= 0");
  Random rnd(seed ^ static_cast<std::uint32_t>(index * 2654435761LL));
  const int configuration = static_cast<int>(index % 6);
  const Stack s = makeStack(configuration, rnd);
  const core::Aabb boxA = core::boundingBox(s.a);
  const core::Aabb boxB = core::boundingBox(s.b);
  const double gap = drawGap(rnd, s.feature);
  const Vector3d contact(s.offset.x(), s.offset.y(), boxA.max.z());
  // B's lowest point, at the middle of its box across, over the contact point.
  const Vector3d lowB(0.5 * (boxB.min.x() + boxB.max.x()), 0.5 * (boxB.min.y() + boxB.max.y()),
                      boxB.min.z());
  const core::TriangleMesh b = core::transformed(
      s.b, pose(Eigen::Matrix3d::Identity(), contact - lowB + Vector3d(0.0, 0.0, gap)));
  // Each block turned (or, one time in four, not) about the contact point.
  const Turn ta = rnd.index(4) == 0 ? Turn{} : smallTurn(rnd);
  const Turn tb = rnd.index(4) == 0 ? Turn{} : smallTurn(rnd);
  PropertyCase c;
  c.a = turnedAbout(s.a, ta, contact);
  c.b = turnedAbout(b, tb, contact);
  static constexpr std::array<core::ViewAxis, 4> kAxes = {core::ViewAxis::Z, core::ViewAxis::Z,
                                                          core::ViewAxis::X, core::ViewAxis::Y};
  static constexpr std::array<int, 4> kWidths = {128, 256, 512, 1024};
  core::ViewSpec view;
  view.axis = kAxes[static_cast<std::size_t>(rnd.index(4))];
  core::FrameOverrides overrides;
  overrides.width = kWidths[static_cast<std::size_t>(rnd.index(4))];
  overrides.height = overrides.width;
  core::Aabb bounds = core::boundingBox(c.a);
  bounds.extend(core::boundingBox(c.b));
  c.frame = core::resolveFrame(view, bounds, overrides);
  c.label = caseLabel(s.name, index, ta, tb, gap, view.axis, *overrides.width);
  return c;
}

void checkModeProperties(long long first, long long count, std::uint32_t seed,
                         core::AdaptivePairTester& tester, PropertyTally& tally) {
  for (long long i = first; i < first + count; ++i) {
    const PropertyCase c = propertyCase(i, seed);
    const bool exact = exactlyIntersect(c.a, c.b);
    const ModeCheck m = checkModes(c.a, c.b, c.frame, exact, tester);
    ++tally.cases;
    tally.intersect += exact ? 1 : 0;
    tally.referenceMissed += exact && !m.referenceCollide ? 1 : 0;
    if (exact && !m.conservativeCollide) {
      ++tally.conservativeMissed;
      fail(tally, c, "the conservative mode missed it");
    }
    if (m.referenceCollide && !m.conservativeCollide) {
      ++tally.conservativeBelowReference;
      fail(tally, c, "the reference says collide, the conservative mode apart");
    }
    if (exact && m.adaptive == core::PairVerdict::Apart) {
      ++tally.adaptiveFalseApart;
      fail(tally, c, "the adaptive mode says a definite apart");
    }
    tally.adaptiveApartAtLimit += m.adaptive == core::PairVerdict::ApartAtLimit ? 1 : 0;
    if (m.conservativeCollide && !exact) {
      ++tally.conservativeExtras;
      if (!m.conservativeExtraWithinBound) {
        ++tally.conservativeExtrasBeyondBound;
        fail(tally, c, "a conservative extra beyond its bound");
      }
    }
    if (m.referenceCollide && !exact) {
      ++tally.referenceExtras;
      raster::CpuDevice device(c.frame.width, c.frame.height);
      core::PairRequest request;
      request.frame = c.frame;
      const core::PairResult reference = core::collidePair(device, c.a, c.b, request);
      const CgalJudgement j = judgePair(exactIntersection(c.a, c.b), c.frame, c.a, c.b, reference);
      if (j.verdict == VerdictCheck::Disagree) {
        ++tally.referenceExtrasUnexplained;
        fail(tally, c, "a reference extra that is no touch within depth rounding");
      }
    }
  }
}

}  // namespace recode::verify
