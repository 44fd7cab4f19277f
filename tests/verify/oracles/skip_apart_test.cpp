// The skip-apart mode against the reference: a pair core::provenApart rules out must be one the
// reference reports no interfering pixel for, over the generated suite (whose configurations
// include blocks a hair apart, tips held just off faces and faces a hair apart) and over pairs
// swept towards each other in steps of their own slack, across the view and along it, where the
// reference turns from apart to touching. Each test also requires pairs proven apart, so none
// passes by proving nothing.

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/refine/proven_apart.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

namespace {

struct Tally {
  int pairs = 0;
  int proven = 0;    // provenApart
  int collide = 0;   // the reference reports interference
  int violated = 0;  // both: must stay 0
};

// Whether the reference finds interference between the two blocks in `frame`.
bool referenceCollides(const core::PairBlock& a, const core::PairBlock& b,
                       const core::FrameSpec& frame) {
  core::PairRequest request;
  request.frame = frame;
  request.contact = false;
  raster::CpuDevice device(frame.width, frame.height);
  return core::collidePair(device, a, b, request).collide;
}

// Counts one pair decided both ways; proven apart and colliding is a failure.
void count(bool proven, bool collide, Tally& tally) {
  ++tally.pairs;
  tally.proven += proven ? 1 : 0;
  tally.collide += collide ? 1 : 0;
  tally.violated += proven && collide ? 1 : 0;
  if (proven && collide)
    FAIL_CHECK("proven apart, yet the reference reports interference");
}

// Decides one pair both ways and counts it.
void check(const core::TriangleMesh& a, const core::TriangleMesh& b, const core::FrameSpec& frame,
           Tally& tally) {
  const core::PairBlock blockA = core::PairBlock::withHierarchy(a);
  const core::PairBlock blockB = core::PairBlock::withHierarchy(b);
  count(core::provenApart(blockA, blockB, frame), referenceCollides(blockA, blockB, frame), tally);
}

// The same from each block's own mesh and pose, as a simulation proves its pairs: each block is
// given in coordinates of its own (a turn and a shift of the suite's mesh), the reference draws
// the world meshes transformed() makes of them, and the proof reads the local meshes, the
// poses and those world meshes' boxes.
void checkPosed(const core::TriangleMesh& a, const core::TriangleMesh& b,
                const core::FrameSpec& frame, const Eigen::Isometry3d& poseA,
                const Eigen::Isometry3d& poseB, Tally& tally) {
  const core::TriangleMesh localA = core::transformed(a, poseA.inverse());
  const core::TriangleMesh localB = core::transformed(b, poseB.inverse());
  const core::TriangleMesh worldA = core::transformed(localA, poseA);
  const core::TriangleMesh worldB = core::transformed(localB, poseB);
  const core::PairBlock blockA = core::PairBlock::withHierarchy(worldA);
  const core::PairBlock blockB = core::PairBlock::withHierarchy(worldB);
  const bool proven = core::provenApart(
      core::PosedBlock{localA, poseA, blockA.box(), core::drawableExtent(localA)},
      core::PosedBlock{localB, poseB, blockB.box(), core::drawableExtent(localB)}, frame);
  count(proven, referenceCollides(blockA, blockB, frame), tally);
}

core::FrameSpec frameOver(const core::TriangleMesh& a, const core::TriangleMesh& b,
                          core::ViewAxis axis, int width) {
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::ViewSpec view;
  view.axis = axis;
  return core::resolveFrame(view, bounds, {width, {}, {}});
}

core::TriangleMesh moved(core::TriangleMesh mesh, const Eigen::Vector3d& by) {
  for (Eigen::Vector3d& p : mesh.vertices)
    p += by;
  return mesh;
}

}  // namespace

TEST_CASE("skip-apart: no pair of the generated suite proven apart interferes in the reference") {
  for (const int width : {64, 256}) {
    verify::PairSuiteOptions options;
    options.width = width;
    options.count = width == 64 ? 504 : 112;
    std::map<std::string, Tally> byConfiguration;
    Tally all;
    for (const verify::SuitePair& p : verify::generatePairSuite(options)) {
      INFO(p.label << " at width " << width);
      Tally& t = byConfiguration[std::string(verify::toString(p.configuration))];
      Tally one;
      check(p.a, p.b, p.frame, one);
      t.pairs += one.pairs, t.proven += one.proven, t.collide += one.collide;
      t.violated += one.violated;
      all.pairs += one.pairs, all.proven += one.proven, all.collide += one.collide;
      all.violated += one.violated;
    }
    for (const auto& [name, t] : byConfiguration)
      INFO(name << ": " << t.pairs << " pairs, " << t.proven << " proven apart, " << t.collide
                << " colliding");
    CHECK(all.violated == 0);
    // Most pairs the reference sees apart are proven apart; the hair-apart configuration's
    // pairs are there too, or the boundary would be untested.
    CHECK(all.proven > (all.pairs - all.collide) / 2);
    CHECK(byConfiguration.at("just-separated").proven > 0);
  }
}

TEST_CASE(
    "skip-apart from local meshes and poses: no pair of the generated suite proven apart "
    "interferes in the reference") {
  verify::PairSuiteOptions options;
  options.width = 64;
  options.count = 504;
  Tally all;
  int justSeparatedProven = 0;
  int k = 0;
  for (const verify::SuitePair& p : verify::generatePairSuite(options)) {
    INFO(p.label);
    // Each block's own coordinates: turned by a different angle about a different axis, and
    // far from the world's origin, so that the poses' rounding is in play.
    const auto pose = [](int n) {
      Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
      t.rotate(Eigen::AngleAxisd(
          0.37 * n + 0.1, Eigen::Vector3d(std::sin(n), std::cos(2.0 * n), 0.5).normalized()));
      t.pretranslate(Eigen::Vector3d(40.0 + n, -25.0, 13.0 * std::sin(n)));
      return t;
    };
    Tally one;
    checkPosed(p.a, p.b, p.frame, pose(2 * k), pose(2 * k + 1), one);
    ++k;
    all.pairs += one.pairs, all.proven += one.proven, all.collide += one.collide;
    all.violated += one.violated;
    if (p.configuration == verify::PairConfiguration::JustSeparated)
      justSeparatedProven += one.proven;
  }
  INFO(all.pairs << " pairs, " << all.proven << " proven apart, " << all.collide << " colliding");
  CHECK(all.violated == 0);
  CHECK(all.proven > (all.pairs - all.collide) / 2);
  CHECK(justSeparatedProven > 0);
}

TEST_CASE(
    "skip-apart: boxes swept together face on face are proven apart only while the "
    "reference sees them apart") {
  // Two boxes turned alike (so their faces are tilted planes of sliver-free but sloped
  // triangles), B closing on A along A's face normal: that normal points mostly along the view,
  // where the reference turns from apart to touching within a depth step, or mostly across it.
  // The gaps step by an eighth of a depth step up to two steps (gaps under a step may be
  // quantised to touching, which a tilted face shows at every alignment), then by a quarter of
  // the pair's slack along the normal up to three slacks, where the proof must hold.
  const core::TriangleMesh box = core::makeBox(0.5, 0.4, 0.3);
  Tally tally;
  int provenAtThreeSlacks = 0, approaches = 0;
  for (const core::ViewAxis axis : {core::ViewAxis::Z, core::ViewAxis::X}) {
    for (const double tilt : {0.0, 0.05, 0.3}) {
      for (int face = 0; face < 3; ++face) {
        INFO("view " << core::toString(axis) << ", tilt " << tilt << ", face " << face);
        ++approaches;
        const Eigen::Matrix3d turn =
            Eigen::AngleAxisd(tilt, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
        core::TriangleMesh a = box;
        for (Eigen::Vector3d& p : a.vertices)
          p = turn * p;
        const Eigen::Vector3d normal = turn.col(face);
        const double width = 2.0 * box.vertices[0].cwiseAbs()[face];
        const core::TriangleMesh touching = moved(a, normal * width);
        const core::FrameSpec frame = frameOver(a, touching, axis, 128);
        const core::PairBlock blockA = core::PairBlock::withHierarchy(a);
        const core::PairBlock blockB = core::PairBlock::withHierarchy(touching);
        const auto [depthMin, depthMax] =
            core::pairDepthRange(frame.axis, blockA.box(), blockB.box());
        const core::OrthoView view(frame.axis, frame.window, frame.width, frame.height, depthMin,
                                   depthMax);
        const double slack =
            (core::fragmentSlack(view, blockA.box()) + core::fragmentSlack(view, blockB.box()))
                .dot(normal.cwiseAbs());
        REQUIRE(slack > 0.0);
        // Gaps of eighths of a depth step up to two steps, where quantisation decides touching,
        // then quarters of the slack up to three slacks.
        const double depthStep = (depthMax - depthMin) / 16777215.0;
        std::vector<double> gaps;
        for (int j = -8; j <= 16; ++j)
          gaps.push_back(depthStep * j / 8.0);
        for (int k = 1; k <= 12; ++k)
          gaps.push_back(slack * k / 4.0);
        for (const double gap : gaps) {
          INFO("gap " << gap / slack << " slacks");
          Tally step;
          check(a, moved(touching, normal * gap), frame, step);
          tally.pairs += step.pairs, tally.proven += step.proven, tally.collide += step.collide;
          tally.violated += step.violated;
          if (gap == gaps.back())
            provenAtThreeSlacks += step.proven;
        }
      }
    }
  }
  INFO(tally.pairs << " pairs, " << tally.proven << " proven apart, " << tally.collide
                   << " colliding");
  CHECK(tally.violated == 0);
  CHECK(tally.collide > 0);
  CHECK(provenAtThreeSlacks == approaches);
}

TEST_CASE(
    "skip-apart: a pair the reference refuses is not proven apart, so it is refused as "
    "before") {
  // Two flat squares in the plane z = 0, drawn along z: the pair's depth range is empty, which
  // the view refuses. provenApart must say false (not throw), leaving collidePair's error.
  core::TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const core::TriangleMesh other = moved(square, {3.0, 0.0, 0.0});
  const core::PairBlock a(square), b(other);
  core::PairRequest request;
  request.frame.axis = core::ViewAxis::Z;
  request.frame.window = {-1.0, -1.0, 5.0, 2.0};
  request.frame.width = 60;
  request.frame.height = 30;
  bool proven = true;
  CHECK_NOTHROW(proven = core::provenApart(a, b, request.frame));
  CHECK_FALSE(proven);
  raster::CpuDevice device(60, 30);
  CHECK_THROWS_AS(core::collidePair(device, a, b, request), std::invalid_argument);
}

TEST_CASE("skip-apart from local meshes: a block that cannot be drawn is never proven apart") {
  // Two boxes far apart: proven apart, unless a vertex is not finite (the reference refuses the
  // block) or the pose could overflow a world coordinate. (GJK's squared lengths overflow on so
  // far a pose as well, and it then proves nothing; the bound on the pose makes the refusal not
  // depend on that.)
  const core::TriangleMesh box = core::makeBox(0.5, 0.5, 0.5);
  const core::TriangleMesh far = moved(box, {4.0, 0.0, 1.0});
  const core::FrameSpec frame = frameOver(box, far, core::ViewAxis::Z, 128);
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  const core::Aabb boxA = core::boundingBox(box), boxB = core::boundingBox(far);
  const double extentA = core::drawableExtent(box), extentB = core::drawableExtent(far);
  CHECK(core::provenApart(core::PosedBlock{box, identity, boxA, extentA},
                          core::PosedBlock{far, identity, boxB, extentB}, frame));
  core::TriangleMesh broken = box;
  broken.vertices[3].x() = std::nan("");
  CHECK_FALSE(
      core::provenApart(core::PosedBlock{broken, identity, boxA, core::drawableExtent(broken)},
                        core::PosedBlock{far, identity, boxB, extentB}, frame));
  Eigen::Isometry3d huge = identity;
  huge.translation() = Eigen::Vector3d(1e301, 0.0, 0.0);
  CHECK_FALSE(core::provenApart(core::PosedBlock{box, huge, boxA, extentA},
                                core::PosedBlock{far, identity, boxB, extentB}, frame));
}
