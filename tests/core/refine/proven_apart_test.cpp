// The skip-apart test (core/refine proven_apart.hpp) on values its bounds are defined by: the
// fragment slack of a block from the frame's pixel and depth step, and the proof on blocks
// given as local meshes and poses, which holds only for hulls apart beyond the slacks.

#include <catch2/catch.hpp>
#include <cmath>

#include <Eigen/Geometry>

#include "recode/geometry/generators.hpp"
#include "recode/pair/view.hpp"
#include "recode/raster/state.hpp"
#include "recode/refine/proven_apart.hpp"

using namespace recode;
using Eigen::Vector3d;

namespace {

// Seen along z over [0, 16]^2 at 16 x 16 (pixels of exactly 1) with the depth range [0, 1]: a
// block's extent in pixels is its extent in world units, and the depth slack is its fraction
// of the range as it is.
core::OrthoView unitView() {
  return core::OrthoView(core::ViewAxis::Z, {0, 0, 16, 16}, 16, 16, 0.0, 1.0);
}

core::Aabb boxFromOrigin(double x) {
  core::Aabb box;
  box.min = Vector3d(0, 0, 0);
  box.max = Vector3d(x, 0, 1);
  return box;
}

// Half a depth step for the rounding and half for the quantisation, doubled, plus the plane's
// rounding bound 2^-47 E^2 with E = 256 (pixels + 1), of a unit depth range.
double depthSlack(double pixels) {
  const double e = 256.0 * (pixels + 1.0);
  return 2.0 / static_cast<double>(raster::kDepthMax) + std::ldexp(e * e, -47);
}

}  // namespace

TEST_CASE("the fragment slack is 1/256 pixel across and two depth steps and the rounding along") {
  const core::OrthoView view = unitView();
  const Vector3d point = core::fragmentSlack(view, boxFromOrigin(0.0));
  CHECK(point.x() == 1.0 / 256.0);
  CHECK(point.y() == 1.0 / 256.0);
  // A block of no extent: E = 256, the plane's bound 2^16 2^-47 = 2^-31. 2 / (2^24 - 1) is a
  // double with bits from 2^-23 to 2^-71, so the sum is exact and any other step shows.
  CHECK(point.z() == 2.0 / 16777215.0 + std::ldexp(1.0, -31));
  // 0.3706... pixels across (a double of full precision): E = 256 (1 + 0.3706...), whose square
  // carries bits below the sum's last place; the value is the bound's, rounded as written.
  const double pixels = 0x1.7b7ffec284604p-2;
  CHECK(core::fragmentSlack(view, boxFromOrigin(pixels)).z() == depthSlack(pixels));
}

TEST_CASE("blocks given by local meshes and poses are proven apart only beyond the slacks") {
  // Unit cubes drawn along z over [-4, 4]^2 at 64 x 64: one at the origin, the other moved
  // along x by 0.5 (overlapping), by 1 (touching) and by 3 (a gap of 2, far beyond the slacks
  // of 1/256 of a pixel of 0.125 and a few depth steps).
  const core::TriangleMesh cube = core::makeBox(0.5, 0.5, 0.5);
  const double extent = core::drawableExtent(cube);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const core::Aabb box = core::boundingBox(cube);
  core::FrameSpec frame;
  frame.axis = core::ViewAxis::Z;
  frame.window = {-4, -4, 4, 4};
  frame.width = 64;
  frame.height = 64;
  for (const double dx : {0.5, 1.0, 3.0}) {
    INFO("moved by " << dx);
    Eigen::Isometry3d pose = identity;
    pose.translation() = Vector3d(dx, 0, 0);
    core::Aabb moved = box;
    moved.min.x() += dx;
    moved.max.x() += dx;
    const bool proven = core::provenApart(core::PosedBlock{cube, identity, box, extent},
                                          core::PosedBlock{cube, pose, moved, extent}, frame);
    CHECK(proven == (dx > 1.0));
  }
}

TEST_CASE("world blocks are proven apart only beyond the slacks and never when one has no vertex") {
  // The cubes of the test above as world meshes (a PairBlock refers to its mesh): at the origin and
  // moved along x by 0.5 (overlapping), 1 (touching) and 3 (a gap of 2, far beyond the slacks).
  const core::TriangleMesh cube = core::makeBox(0.5, 0.5, 0.5);
  core::FrameSpec frame;
  frame.axis = core::ViewAxis::Z;
  frame.window = {-4, -4, 4, 4};
  frame.width = 64;
  frame.height = 64;
  const core::PairBlock a(cube);
  for (const double dx : {0.5, 1.0, 3.0}) {
    INFO("moved by " << dx);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Vector3d(dx, 0, 0);
    const core::TriangleMesh moved = core::transformed(cube, pose);
    const core::PairBlock b(moved);
    CHECK(core::provenApart(a, b, frame) == (dx > 1.0));
    CHECK(core::provenApart(b, a, frame) == (dx > 1.0));
  }
  // A block without vertices proves nothing, on either side.
  const core::TriangleMesh none;
  const core::PairBlock empty(none);
  CHECK_FALSE(core::provenApart(a, empty, frame));
  CHECK_FALSE(core::provenApart(empty, a, frame));
}
