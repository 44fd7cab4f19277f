// The layered pair on the CPU device: closed meshes that are not convex (a torus, a hollow
// ball, interlocked rings), containment, the overlap volume against one computed by hand, the
// refusal of a mesh that is not closed, and agreement with RECODE's passes on convex pairs.

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "recode/geometry/generators.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"

#include "closed_mesh_support.hpp"
#include "pair_test_support.hpp"

using namespace recode;
using core::Containment;
using core::ViewAxis;
using Eigen::Vector3d;

using recode::test::frameAround;

namespace {

core::LayeredPairResult runLayered(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                   const core::FrameSpec& frame,
                                   core::MorMode mor = core::MorMode::Min) {
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  request.mor = mor;
  return core::collideLayered(device, a, b, request);
}

core::TriangleMesh turnedAboutX(const core::TriangleMesh& m, const Vector3d& offset) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(0.5 * std::numbers::pi, Vector3d::UnitX()).toRotationMatrix();
  t.translation() = offset;
  return core::transformed(m, t);
}

constexpr ViewAxis kAxes[] = {ViewAxis::X, ViewAxis::Y, ViewAxis::Z};

}  // namespace

TEST_CASE("a ball in a torus's hole does not touch it, seen along every axis") {
  const core::TriangleMesh torus = core::makeTorus(2.0, 0.5, 48, 24);
  const core::TriangleMesh ball = core::makeSphere(0.5, 24, 12);
  for (const ViewAxis axis : kAxes) {
    INFO("axis " << static_cast<int>(axis));
    const core::LayeredPairResult r = runLayered(torus, ball, frameAround(axis, torus, ball, 96));
    CHECK(r.boxesOverlap);  // the ball lies inside the torus's box: the passes ran
    CHECK_FALSE(r.collide);
    CHECK(r.interferingPixels == 0);
    CHECK(r.overlapVolume == 0.0);
    CHECK(r.containment == Containment::None);
    // The MOR is the ball's footprint. Seen across the ring (X, Y) its rays meet the tube
    // twice: two layers; seen along the ring's axis they pass through the hole: none.
    CHECK(r.layersA == (axis == ViewAxis::Z ? 0 : 2));
    CHECK(r.layersB == 1);
    CHECK(r.passes == 4 + 2 * (r.layersA + r.layersB));
  }
}

TEST_CASE("a ball inside the torus's tube collides and is contained") {
  const core::TriangleMesh torus = core::makeTorus(2.0, 0.5, 48, 24);
  const core::TriangleMesh ball = test::shifted(core::makeSphere(0.2, 16, 8), {2.0, 0.0, 0.0});
  for (const ViewAxis axis : kAxes) {
    INFO("axis " << static_cast<int>(axis));
    const core::LayeredPairResult r = runLayered(torus, ball, frameAround(axis, torus, ball, 128));
    CHECK(r.collide);
    CHECK(r.containment == Containment::BInsideA);
    // Every pixel the ball covers interferes, and its whole depth there is inside the tube.
    const double ballVolume = 4.0 / 3.0 * std::numbers::pi * 0.2 * 0.2 * 0.2;
    CHECK(r.overlapVolume == Approx(ballVolume).epsilon(0.15));
  }
  // Swapped: A is the one inside.
  const core::LayeredPairResult s =
      runLayered(ball, torus, frameAround(ViewAxis::Z, ball, torus, 128));
  CHECK(s.containment == Containment::AInsideB);
}

TEST_CASE("a ball in a hollow ball's cavity does not touch it; in its wall it does") {
  const core::TriangleMesh shell = test::makeHollowBall(2.0, 1.5, 32, 16);
  const core::TriangleMesh inCavity = core::makeSphere(0.5, 16, 8);
  const core::TriangleMesh inWall = test::shifted(core::makeSphere(0.1, 12, 6), {1.75, 0, 0});
  for (const ViewAxis axis : kAxes) {
    INFO("axis " << static_cast<int>(axis));
    const core::LayeredPairResult apart =
        runLayered(shell, inCavity, frameAround(axis, shell, inCavity, 96));
    CHECK_FALSE(apart.collide);
    CHECK(apart.layersA == 2);
    const core::LayeredPairResult wall =
        runLayered(shell, inWall, frameAround(axis, shell, inWall, 160));
    CHECK(wall.collide);
    // Seen along x the small ball's pixels are the ones where the ray crosses the cavity too:
    // the ball is inside the wall's interval there all the same.
    CHECK(wall.containment == Containment::BInsideA);
  }
}

TEST_CASE("interlocked rings: apart with clearance, colliding when pushed together") {
  const core::TriangleMesh a = core::makeTorus(2.0, 0.5, 48, 16);
  // B's circle passes through A's hole and stays 2 from A's tube circle: a clearance of 1.
  const core::TriangleMesh linked = turnedAboutX(core::makeTorus(2.0, 0.5, 48, 16), {2, 0, 0});
  const core::TriangleMesh pushed = turnedAboutX(core::makeTorus(2.0, 0.5, 48, 16), {3.2, 0, 0});
  for (const ViewAxis axis : kAxes) {
    INFO("axis " << static_cast<int>(axis));
    CHECK_FALSE(runLayered(a, linked, frameAround(axis, a, linked, 128)).collide);
    const core::LayeredPairResult r = runLayered(a, pushed, frameAround(axis, a, pushed, 128));
    CHECK(r.collide);
    CHECK(r.containment == Containment::None);
  }
}

TEST_CASE("overlapping boxes: the interfering pixels and the volume, counted by hand") {
  // [0, 2]^3 and [1, 3]^3 overlap in the unit cube [1, 2]^3. The window is placed so that no
  // pixel centre lies on a face: the interfering pixels are the centres inside [1, 2]^2.
  const core::TriangleMesh a = test::boxBetween({0, 0, 0}, {2, 2, 2});
  const core::TriangleMesh b = test::boxBetween({1, 1, 1}, {3, 3, 3});
  const core::FrameSpec frame = test::frameZ(-0.513, -0.487, 3.487, 3.513, 80, 80);
  const double pixel = 4.0 / 80;
  const auto centresIn = [&](double lo, double hi, double origin) {
    int n = 0;
    for (int i = 0; i < 80; ++i) {
      const double c = origin + (i + 0.5) * pixel;
      n += (c >= lo && c <= hi) ? 1 : 0;
    }
    return n;
  };
  const long long expectedPixels = centresIn(1.0, 2.0, -0.513) * centresIn(1.0, 2.0, -0.487);
  const core::LayeredPairResult r = runLayered(a, b, frame);
  CHECK(r.interferingPixels == expectedPixels);
  // Depth [0, 3] onto 2^24 - 1 steps: the unit overlap is 1/3 of them, within a step at each end.
  const double step = 3.0 / raster::kDepthMax;
  const double columns = static_cast<double>(expectedPixels) * pixel * pixel;
  CHECK(std::abs(r.overlapVolume - columns * 1.0) <= columns * 2.0 * step);
  CHECK(r.contact.maxDepth == Approx(1.0).margin(2.0 * step));
  CHECK(r.containment == Containment::None);
  CHECK(r.layersA == 1);
  CHECK(r.stencilPixelsRead == 4 * r.mor.area());
}

TEST_CASE("a mesh with a hole is refused where the view sees it unbalanced") {
  core::TriangleMesh open = core::makeSphere(1.0, 16, 8);
  open.triangles.erase(open.triangles.begin() + 40);  // a triangle of the side facing +z
  const core::TriangleMesh ball = core::makeSphere(0.5, 16, 8);
  const core::FrameSpec frame = frameAround(ViewAxis::Z, open, ball, 64);
  CHECK_THROWS_WITH(runLayered(open, ball, frame),
                    Catch::Contains("mesh A is not closed as the view sees it: pixel (") &&
                        Catch::Contains("back-facing fragments"));
  CHECK_THROWS_WITH(runLayered(ball, open, frame), Catch::Contains("mesh B is not closed"));
}

TEST_CASE("boxes apart: nothing is drawn, as in collidePair") {
  const core::TriangleMesh a = core::makeSphere(1.0, 16, 8);
  const core::TriangleMesh b = test::shifted(a, {5, 0, 0});
  const core::LayeredPairResult r = runLayered(a, b, frameAround(ViewAxis::Z, a, b, 64));
  CHECK_FALSE(r.boxesOverlap);
  CHECK_FALSE(r.collide);
  CHECK(r.passes == 0);
  CHECK(r.mor.empty());
}

TEST_CASE("convex pairs: the layered pair interferes where RECODE's passes do") {
  std::mt19937 rng(20261207);
  std::uniform_real_distribution<double> offset(-1.6, 1.6), angle(0.0, 2.0 * std::numbers::pi);
  const core::TriangleMesh shapes[] = {core::makeSphere(1.0, 20, 10), core::makeBox(0.8, 0.5, 1.1),
                                       core::makeCone(0.9, 1.8, 16),
                                       core::makeCylinder(0.6, 1.5, 12)};
  int colliding = 0;
  for (int n = 0; n < 60; ++n) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = (Eigen::AngleAxisd(angle(rng), Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(angle(rng), Vector3d::UnitX()))
                        .toRotationMatrix();
    pose.translation() = Vector3d(offset(rng), offset(rng), offset(rng));
    const core::TriangleMesh& a = shapes[n % 4];
    const core::TriangleMesh b = core::transformed(shapes[(n / 4) % 4], pose);
    for (const ViewAxis axis : kAxes) {
      INFO("pair " << n << " axis " << static_cast<int>(axis));
      const core::FrameSpec frame = frameAround(axis, a, b, 48);
      const core::PairResult recode = test::runPair(a, b, frame, core::MorMode::Min, false);
      const core::LayeredPairResult layered = runLayered(a, b, frame);
      REQUIRE(layered.collide == recode.collide);
      REQUIRE(layered.interferingPixels == recode.interferingPixels);
      REQUIRE(layered.mor == recode.mor);
      for (int y = recode.mor.y0; y < recode.mor.y1; ++y)
        for (int x = recode.mor.x0; x < recode.mor.x1; ++x)
          REQUIRE((layered.interferes.at(x, y) != 0) ==
                  core::isInterfering(recode.caseMap.at(x, y)));
      CHECK(layered.layersA <= 1);
      colliding += recode.collide ? 1 : 0;
    }
  }
  CHECK(colliding > 40);  // the poses exercise interference, not only pairs apart
}

TEST_CASE("a probed pixel shows the sweep that decided it, and changes nothing else") {
  // A ball half inside a torus's tube, seen along x: the line through the ring's axis plane
  // crosses the tube twice (two entries and two exits of the torus) and the ball once.
  const core::TriangleMesh torus = core::makeTorus(2.0, 0.6, 48, 20);
  const core::TriangleMesh ball = test::shifted(core::makeSphere(0.5, 24, 12), {2.3, 0.0, 0.0});
  const core::FrameSpec frame = frameAround(ViewAxis::X, torus, ball, 64);
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  const core::PairBlock a(torus), b(ball);
  const core::LayeredPairResult plain = core::collideLayered(device, a, b, request);
  REQUIRE(plain.collide);
  int probed = 0, crossedTwice = 0;
  for (int y = plain.mor.y0; y < plain.mor.y1; ++y)
    for (int x = plain.mor.x0; x < plain.mor.x1; ++x) {
      INFO("pixel " << x << ", " << y);
      const core::LayeredPairResult r =
          core::collideLayered(device, a, b, request, std::array<int, 2>{x, y});
      REQUIRE(r.pixel);
      const core::LayeredPixel& p = *r.pixel;
      CHECK(p.inMor);
      CHECK(r.interferingPixels == plain.interferingPixels);
      CHECK(r.overlapVolume == plain.overlapVolume);
      // Each mesh as many entries as exits, nearest first; the lengths are the pixel's overlap.
      for (const auto* list : {&p.entriesA, &p.exitsA, &p.entriesB, &p.exitsB})
        CHECK(std::is_sorted(list->begin(), list->end()));
      CHECK(p.entriesA.size() == p.exitsA.size());
      CHECK(p.entriesB.size() == p.exitsB.size());
      std::uint64_t steps = 0;
      for (const core::DepthInterval& d : p.insideBoth)
        steps += d.max - d.min;
      CHECK(steps == plain.overlapSteps.at(x, y));
      CHECK((p.insideBoth.empty() ? 0 : 1) == plain.interferes.at(x, y));
      if (p.entriesA.size() == 2) {  // through both sides of the tube: entry, exit, entry, exit
        ++crossedTwice;
        CHECK(p.entriesA[0] < p.exitsA[0]);
        CHECK(p.exitsA[0] < p.entriesA[1]);
        CHECK(p.entriesA[1] < p.exitsA[1]);
        CHECK(p.insideA.size() == 2);
      }
      ++probed;
    }
  CHECK(probed > 50);
  CHECK(crossedTwice > 10);
  // Outside the MOR: every list empty.
  const core::LayeredPairResult outside =
      core::collideLayered(device, a, b, request, std::array<int, 2>{0, 0});
  REQUIRE(outside.pixel);
  CHECK_FALSE(outside.pixel->inMor);
  CHECK(outside.pixel->entriesA.empty());
  CHECK(outside.pixel->insideBoth.empty());
}
