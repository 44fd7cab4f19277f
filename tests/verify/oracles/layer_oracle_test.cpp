// The layered pair against CGAL: every pixel against exact crossings under the contract's fill
// rule, every pose's verdict against CGAL's do_intersect with the bounded-sides test, and the
// overlap volume against CGAL's corefinement, on closed meshes that are not convex.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "recode/geometry/generators.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/layer_oracle.hpp"

#include "closed_mesh_support.hpp"

using namespace recode;
using Eigen::Vector3d;

using recode::test::frameAround;

namespace {

core::LayeredPairResult runLayered(const core::TriangleMesh& a, const core::TriangleMesh& b,
                                   const core::FrameSpec& frame) {
  raster::CpuDevice device(frame.width, frame.height);
  core::PairRequest request;
  request.frame = frame;
  return core::collideLayered(device, a, b, request);
}

Eigen::Isometry3d randomPose(std::mt19937& rng, double reach) {
  std::uniform_real_distribution<double> offset(-reach, reach), angle(0.0, 2.0 * std::numbers::pi);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(angle(rng), Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(angle(rng), Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = Vector3d(offset(rng), offset(rng), offset(rng));
  return pose;
}

}  // namespace

TEST_CASE("the layered pair's pixels and verdicts against CGAL, ring against ring and ball") {
  const core::TriangleMesh ring = core::makeTorus(2.0, 0.5, 40, 16);
  const core::TriangleMesh movers[] = {core::makeTorus(1.5, 0.4, 32, 12),
                                       core::makeSphere(0.45, 16, 8),
                                       test::makeHollowBall(1.0, 0.7, 16, 8)};
  std::mt19937 rng(7081);
  long long pixels = 0, ties = 0, contained = 0, colliding = 0, apart = 0;
  for (int n = 0; n < 36; ++n) {
    const core::TriangleMesh b = core::transformed(movers[n % 3], randomPose(rng, 2.2));
    const auto axis = static_cast<core::ViewAxis>(n % 3);
    const core::FrameSpec frame = frameAround(axis, ring, b, 128);
    const core::LayeredPairResult r = runLayered(ring, b, frame);
    INFO("pose " << n);
    const verify::LayerPixelJudgement j = verify::judgeLayeredPixels(ring, b, frame, r);
    CHECK(j.disagreed == 0);
    pixels += j.pixels;
    ties += j.ties;
    const bool exact = verify::closedMeshesMeet(ring, b);
    // The pixels decide the verdict: where some pixel centre sees the exact interiors meet, the
    // device must say so; where it collides, CGAL must too (a tie pixel aside).
    if (j.exactInterfering > 0)
      CHECK(r.collide);
    if (r.collide && j.ties == 0)
      CHECK(exact);
    if (!exact)
      CHECK(j.exactInterfering == 0);
    contained += r.containment != core::Containment::None ? 1 : 0;
    colliding += r.collide ? 1 : 0;
    apart += exact ? 0 : 1;
  }
  WARN("layer judge: " << pixels << " MOR pixels, " << ties << " ties; " << colliding
                       << " poses colliding, " << apart << " apart, " << contained << " contained");
  CHECK(colliding >= 8);
  CHECK(apart >= 8);
  CHECK(ties * 1000 <= pixels);  // ties are rare: at most one pixel in a thousand
}

TEST_CASE("a ball inside a ring's tube: contained for the pixels and for CGAL") {
  const core::TriangleMesh ring = core::makeTorus(2.0, 0.5, 40, 16);
  const core::TriangleMesh ball = test::shifted(core::makeSphere(0.25, 16, 8), {0.0, 2.0, 0.1});
  for (const auto axis : {core::ViewAxis::X, core::ViewAxis::Y, core::ViewAxis::Z}) {
    const core::FrameSpec frame = frameAround(axis, ring, ball, 160);
    const core::LayeredPairResult r = runLayered(ring, ball, frame);
    CHECK(r.containment == core::Containment::BInsideA);
    CHECK(verify::judgeLayeredPixels(ring, ball, frame, r).disagreed == 0);
  }
  CHECK(verify::closedMeshesMeet(ring, ball));
}

TEST_CASE("the overlap volume approaches CGAL's corefinement as the pixels shrink") {
  const core::TriangleMesh ring = core::makeTorus(2.0, 0.6, 48, 20);
  const core::TriangleMesh ball = test::shifted(core::makeSphere(0.8, 24, 12), {2.0, 0.3, 0.2});
  const double exact = verify::closedMeshesOverlapVolume(ring, ball);
  REQUIRE(exact > 0.1);
  double previous = 1e300;
  for (const int width : {64, 128, 256, 512, 1024}) {
    const core::FrameSpec frame = frameAround(core::ViewAxis::Z, ring, ball, width);
    const double error = std::abs(runLayered(ring, ball, frame).overlapVolume - exact) / exact;
    WARN("volume at " << width << " px: relative error " << error);
    CHECK(error < previous * 1.1);  // no worse at a finer grid (up to the sampling's noise)
    previous = error;
  }
  CHECK(previous < 0.02);
}

TEST_CASE("the layer judge fails a result whose pixels were changed") {
  const core::TriangleMesh ring = core::makeTorus(2.0, 0.5, 40, 16);
  const core::TriangleMesh ball = test::shifted(core::makeSphere(0.5, 16, 8), {2.0, 0.0, 0.0});
  const core::FrameSpec frame = frameAround(core::ViewAxis::Z, ring, ball, 96);
  core::LayeredPairResult r = runLayered(ring, ball, frame);
  REQUIRE(verify::judgeLayeredPixels(ring, ball, frame, r).disagreed == 0);
  // The pixel at the ball's centre interferes well inside: clearing it is a defect, not a tie.
  const int x = frame.width / 2 +
                static_cast<int>(2.0 / (frame.window.umax - frame.window.umin) * frame.width);
  const int y = frame.height / 2;
  REQUIRE(r.interferes.at(x, y) == 1);
  r.interferes.at(x, y) = 0;
  const verify::LayerPixelJudgement j = verify::judgeLayeredPixels(ring, ball, frame, r);
  CHECK(j.disagreed == 1);
  REQUIRE(j.firstDisagreements.size() == 1);
  CHECK(j.firstDisagreements[0] == std::array<int, 2>{x, y});
}

TEST_CASE("pixel centres on edges and vertices: the fill rule decides them, in the judge too") {
  // One world unit a pixel, every box corner on a half-integer: the boxes' side edges and their
  // faces' diagonals pass through pixel centres, and some corners sit on them. The contract's
  // fill rule gives each centre to one triangle of a shared edge; a judge that re-cast the line
  // or took both sides would see more entries than exits there.
  // The top face split along the other diagonal than the bottom face: a centre on a diagonal
  // is on an edge of one of them only.
  core::TriangleMesh crossed = core::makeBox(4.0, 4.0, 1.0);
  crossed.triangles[10] = {4, 5, 6};
  crossed.triangles[11] = {5, 7, 6};
  const core::TriangleMesh a = test::shifted(crossed, {6.5, 6.5, 1.0});
  const core::TriangleMesh hollow =
      test::merged(test::shifted(core::makeBox(4.0, 4.0, 2.0), {10.5, 6.5, 1.5}),
                   test::reversed(test::shifted(core::makeBox(2.0, 2.0, 1.0), {10.5, 6.5, 1.5})));
  core::FrameSpec frame;
  frame.axis = core::ViewAxis::Z;
  frame.window = {0.0, 0.0, 16.0, 16.0};
  frame.width = frame.height = 16;
  for (const core::TriangleMesh* b : {&hollow, &a}) {
    INFO((b == &a ? "the box against itself, raised" : "a hollow box"));
    const core::TriangleMesh moved = test::shifted(*b, {0.0, 0.0, 0.5});
    const core::LayeredPairResult r = runLayered(a, moved, frame);
    const verify::LayerPixelJudgement j = verify::judgeLayeredPixels(a, moved, frame, r);
    CHECK(j.pixels > 0);
    CHECK(j.disagreed == 0);
    CHECK(j.ties == 0);
    CHECK(r.collide);
  }
}
