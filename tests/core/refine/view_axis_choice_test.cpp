// The adaptive view axis (core/refine view_axis_choice.hpp) on constructed pairs whose answer
// follows from the rules' definitions: two thin plates stacked along one axis, a pair of boxes
// apart, plates tilted away from every world axis, and the frame rebuilt along another axis.

#include <cmath>
#include <string_view>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/refine/view_axis_choice.hpp"

using namespace recode;
using core::ViewAxis;
using core::ViewAxisRule;
using Eigen::Vector3d;

namespace {

core::TriangleMesh boxBetween(const Vector3d& lo, const Vector3d& hi) {
  const Eigen::Affine3d move(Eigen::Translation3d(0.5 * (lo + hi)));
  return core::transformed(core::makeBox(0.5 * (hi - lo)), move);
}

// Two plates 2 wide along x, 1.2 along y, 0.1 thick along z, overlapping by 0.02 in z: the
// boxes' intersection is 2 x 1.2 x 0.02.
struct Plates {
  core::TriangleMesh a = boxBetween({-1, -0.6, -0.1}, {1, 0.6, 0.0});
  core::TriangleMesh b = boxBetween({-1, -0.6, -0.02}, {1, 0.6, 0.08});
};

ViewAxis chosen(ViewAxisRule rule, ViewAxis scene, const core::TriangleMesh& a,
                const core::TriangleMesh& b) {
  return core::chooseViewAxis(rule, scene, core::axisChoiceInput(a, b, 0.05));
}

}  // namespace

TEST_CASE("stacked thin plates: each rule picks the axis its definition names") {
  const Plates p;
  for (const ViewAxis scene : {ViewAxis::X, ViewAxis::Y, ViewAxis::Z}) {
    INFO("scene axis " << core::toString(scene));
    CHECK(chosen(ViewAxisRule::Scene, scene, p.a, p.b) == scene);
    // The thinnest overlap is along z (0.02): looking along it keeps the 2 x 1.2 overlap.
    CHECK(chosen(ViewAxisRule::WidestOverlap, scene, p.a, p.b) == ViewAxis::Z);
    // The widest overlap is along x (2): looking along it leaves a MOR of 1.2 x 0.02.
    CHECK(chosen(ViewAxisRule::FewestMor, scene, p.a, p.b) == ViewAxis::X);
    // The boxes' least penetration is along their common normal, z.
    CHECK(chosen(ViewAxisRule::Separating, scene, p.a, p.b) == ViewAxis::Z);
  }
}

TEST_CASE("thin-overlap leaves the scene axis only when the overlap across it is under 2 px") {
  const Plates p;  // seen along x the boxes' intersection is 1.2 by 0.02 across
  const auto thin = [&](double pixelSize) {
    return core::chooseViewAxis(ViewAxisRule::ThinOverlap, ViewAxis::X,
                                core::axisChoiceInput(p.a, p.b, pixelSize));
  };
  CHECK(thin(0.05) == ViewAxis::Z);    // 0.02 is 0.4 px: switch to widest-overlap's axis
  CHECK(thin(0.0101) == ViewAxis::Z);  // just under 2 px
  CHECK(thin(0.0099) == ViewAxis::X);  // just over 2 px: the scene axis stays
  // Seen along z the intersection is 2 by 1.2 across: wide at any of these pixel sizes.
  CHECK(core::chooseViewAxis(ViewAxisRule::ThinOverlap, ViewAxis::Z,
                             core::axisChoiceInput(p.a, p.b, 0.05)) == ViewAxis::Z);
}

TEST_CASE("a tie keeps the scene axis, then takes x before y before z") {
  // Square plates: the overlap is 2 along x and y, so fewest-mor has two equal axes.
  const auto a = boxBetween({-1, -1, -0.1}, {1, 1, 0.0});
  const auto b = boxBetween({-1, -1, -0.02}, {1, 1, 0.08});
  CHECK(chosen(ViewAxisRule::FewestMor, ViewAxis::Y, a, b) == ViewAxis::Y);
  CHECK(chosen(ViewAxisRule::FewestMor, ViewAxis::X, a, b) == ViewAxis::X);
  CHECK(chosen(ViewAxisRule::FewestMor, ViewAxis::Z, a, b) == ViewAxis::X);
}

TEST_CASE("blocks whose boxes are apart keep the scene axis under every rule") {
  const auto a = boxBetween({-1, -1, -1}, {0, 1, 1});
  const auto b = boxBetween({0.5, -0.1, -0.1}, {0.6, 0.1, 0.1});
  for (const ViewAxisRule rule : {ViewAxisRule::FewestMor, ViewAxisRule::WidestOverlap,
                                  ViewAxisRule::Separating, ViewAxisRule::ThinOverlap})
    CHECK(chosen(rule, ViewAxis::Y, a, b) == ViewAxis::Y);
}

TEST_CASE("tilted plates: the separating rule follows the plates' normal, not the boxes") {
  // Plates whose normal is turned 30 degrees from x toward y: the normal is nearest x, while
  // their world boxes' thinnest overlap is along z (0.3 against several tenths along x and y).
  const Eigen::AngleAxisd turn(3.14159265358979323846 / 6, Vector3d::UnitZ());
  const core::TriangleMesh plate = core::makeBox(0.05, 1.0, 0.15);
  const Vector3d normal = turn * Vector3d::UnitX();
  const auto a =
      core::transformed(plate, Eigen::Affine3d(Eigen::Translation3d(-0.04 * normal) * turn));
  const auto b =
      core::transformed(plate, Eigen::Affine3d(Eigen::Translation3d(0.04 * normal) * turn));
  CHECK(chosen(ViewAxisRule::Separating, ViewAxis::Z, a, b) == ViewAxis::X);
  CHECK(chosen(ViewAxisRule::WidestOverlap, ViewAxis::X, a, b) == ViewAxis::Z);
}

TEST_CASE("the frame along another axis keeps the pixel size and covers the pair") {
  const Plates p;
  core::Aabb bounds = core::boundingBox(p.a);
  bounds.extend(core::boundingBox(p.b));
  core::FrameSpec base;
  base.axis = ViewAxis::X;
  base.window = {-0.7, -0.2, 0.7, 0.2};  // y, z: pixels 0.05 wide
  base.width = 28;
  base.height = 8;
  CHECK(core::frameAlongAxis(base, ViewAxis::X, bounds).window.umin == base.window.umin);
  const core::FrameSpec z = core::frameAlongAxis(base, ViewAxis::Z, bounds);
  CHECK(z.axis == ViewAxis::Z);
  CHECK((z.window.umax - z.window.umin) / z.width == Approx(0.05));
  CHECK((z.window.vmax - z.window.vmin) / z.height == Approx(0.05));
  CHECK(z.window.umin <= -1.0);
  CHECK(z.window.umax >= 1.0);
  CHECK(z.window.vmin <= -0.6);
  CHECK(z.window.vmax >= 0.6);
}

TEST_CASE("a contact thinner than a pixel across the scene axis is seen along the chosen one") {
  // Plates overlapping by 0.02 along z, seen along x at pixels of 0.05: the overlap lies
  // between pixel rows (the scene axis misses it); along z it covers the whole plate.
  const Plates p;
  core::Aabb bounds = core::boundingBox(p.a);
  bounds.extend(core::boundingBox(p.b));
  core::FrameSpec base;
  base.axis = ViewAxis::X;
  base.window = {-0.7, -0.2, 0.7, 0.2};  // rows' centres at z = -0.175, -0.125, ..., 0.175
  base.width = 28;
  base.height = 8;
  core::PairRequest request;
  request.frame = base;
  raster::CpuDevice sceneDevice(base.width, base.height);
  CHECK_FALSE(core::collidePair(sceneDevice, p.a, p.b, request).collide);
  request.frame = core::frameAlongAxis(
      base, chosen(core::kAdaptiveViewAxisRule, ViewAxis::X, p.a, p.b), bounds);
  raster::CpuDevice device(request.frame.width, request.frame.height);
  const core::PairResult r = core::collidePair(device, p.a, p.b, request);
  CHECK(r.collide);
  CHECK(r.interferingPixels > 100);
}

TEST_CASE("rule names parse and print; 'adaptive' is the measured rule") {
  for (const ViewAxisRule rule :
       {ViewAxisRule::Scene, ViewAxisRule::FewestMor, ViewAxisRule::WidestOverlap,
        ViewAxisRule::Separating, ViewAxisRule::ThinOverlap})
    CHECK(core::parseViewAxisRule(core::toString(rule)) == rule);
  CHECK(core::parseViewAxisRule("adaptive") == core::kAdaptiveViewAxisRule);
  CHECK_FALSE(core::parseViewAxisRule("diagonal"));
  CHECK_FALSE(core::parseViewAxisRule("Scene"));
}

TEST_CASE("thin-overlap looks across the scene axis along both other axes") {
  // Boxes overlapping 0.02 along one axis and 1 or more along the others: seen along any other
  // axis the overlap is 0.4 px thin across (pixels of 0.05), so thin-overlap takes
  // widest-overlap's axis, the thin one; seen along the thin axis itself it is wide.
  for (int thin = 0; thin < 3; ++thin) {
    Vector3d loA(-1, -1.25, -1.5), hiA(1, 1.25, 1.5), loB = loA, hiB = hiA;
    loA[thin] = -0.1;
    hiA[thin] = 0.0;
    loB[thin] = -0.02;
    hiB[thin] = 0.08;
    const auto a = boxBetween(loA, hiA);
    const auto b = boxBetween(loB, hiB);
    for (const ViewAxis scene : {ViewAxis::X, ViewAxis::Y, ViewAxis::Z}) {
      INFO("thin along " << thin << ", scene axis " << core::toString(scene));
      CHECK(core::chooseViewAxis(ViewAxisRule::ThinOverlap, scene,
                                 core::axisChoiceInput(a, b, 0.05)) == static_cast<ViewAxis>(thin));
    }
  }
}

TEST_CASE("thin-overlap keeps the scene axis for an overlap of exactly 2 px across") {
  // Overlap 0.25 along z (exact in doubles), pixels of 0.125: 2 px, not under 2 px.
  const auto a = boxBetween({-1, -0.75, -0.5}, {1, 0.75, 0});
  const auto b = boxBetween({-1, -0.75, -0.25}, {1, 0.75, 0.75});
  CHECK(core::chooseViewAxis(ViewAxisRule::ThinOverlap, ViewAxis::X,
                             core::axisChoiceInput(a, b, 0.125)) == ViewAxis::X);
  CHECK(core::chooseViewAxis(ViewAxisRule::ThinOverlap, ViewAxis::X,
                             core::axisChoiceInput(a, b, 0.125 + 1e-9)) == ViewAxis::Z);
}

TEST_CASE("separating: a plate inside a box is pushed out along the plate's thin axis") {
  // Both centred at the origin: pushing the plate out of the box takes the sum of their
  // half-sides along an axis, 1 + 0.125 along x against 1.25 + 0.5 along y and 1.5 + 0.75
  // along z.
  const auto box = boxBetween({-1, -1.25, -1.5}, {1, 1.25, 1.5});
  const auto plate = boxBetween({-0.125, -0.5, -0.75}, {0.125, 0.5, 0.75});
  for (const ViewAxis scene : {ViewAxis::Y, ViewAxis::Z})
    CHECK(chosen(ViewAxisRule::Separating, scene, box, plate) == ViewAxis::X);
}

TEST_CASE("separating: a cross product of edges exactly 1e-6 long is skipped as parallel") {
  // The closest points of two boxes apart, corner to corner, lie along a cross product of
  // edges; the rule takes such a direction only when the cross product is longer than 1e-6
  // (shorter ones, of nearly parallel edges, have no reliable direction). Box A's first edge is x,
  // box B's is tilted off x by (8, -6) 1e-7 in y and z, so x cross it is (0, 6, 8) 1e-7, of length
  // 1e-6: exactly the double 1e-6 (3-4-5), so it is skipped, pointing along (0, 0.6, 0.8), 53.13
  // degrees from y towards z.
  const double deg = std::acos(-1.0) / 180.0;
  const auto inYz = [&](double angle) {  // the unit direction `angle` degrees from y towards z
    return Vector3d(0, std::cos(angle * deg), std::sin(angle * deg));
  };
  const Vector3d edgeB(std::sqrt(1.0 - 1e-12), 8e-7, -6e-7);
  REQUIRE(Vector3d(1, 0, 0).cross(edgeB).norm() == 1e-6);
  // Both are unit cubes (half-sides 1), A at the origin turned 20 degrees about x (faces across
  // y-z at 20 and 110 degrees), B turned -30 degrees (faces at -30 and 60 degrees) and tilted.
  core::Obb a;
  a.halfExtents = Vector3d::Ones();
  a.axes.col(0) = Vector3d(1, 0, 0);
  a.axes.col(1) = inYz(20);
  a.axes.col(2) = inYz(110);
  core::Obb b;
  b.halfExtents = Vector3d::Ones();
  const Vector3d faceB = inYz(-30);
  b.axes.col(0) = edgeB;
  b.axes.col(1) = (faceB - faceB.dot(edgeB) * edgeB).normalized();
  b.axes.col(2) = edgeB.cross(b.axes.col(1));
  // B's corner -b2 - b3 sits 0.05 from A's corner a2 + a3 along 39 degrees, inside both
  // corners' normal cones (20..110 for A, -30..60 for B reversed), so the gap along a
  // direction l of those cones is 0.05 cos(angle(l, 39 degrees)): the skipped cross (14.13
  // degrees off) would win over A's face at 20 degrees (19 off) and B's at 60 degrees (21 off).
  // Every other direction sees overlap; so do the world boxes (A's reaches 1.28 in y and z,
  // B's down to 0.64 in y and 0.31 in z).
  b.center = a.axes.col(1) + a.axes.col(2) + 0.05 * inYz(39) + b.axes.col(1) + b.axes.col(2);
  const core::AxisChoiceInput input{a.aabb(), b.aabb(), a, b, 0.05};
  // A's face at 20 degrees is nearer y; the skipped cross, at 53.13 degrees, is nearer z.
  CHECK(core::chooseViewAxis(ViewAxisRule::Separating, ViewAxis::X, input) == ViewAxis::Y);
}

TEST_CASE(
    "the list of rule names: scene and the alias adaptive first then the other rules in order") {
  // "scene" first (ViewAxisRule's first value), then "adaptive", then the other four in the
  // enum's declaration order; every name listed parses.
  const std::string_view names = core::viewAxisRuleNames();
  CHECK(names == "scene, adaptive, fewest-mor, widest-overlap, separating, thin-overlap");
  CHECK(core::parseViewAxisRule(names.substr(0, names.find(','))) == ViewAxisRule::Scene);
}
