// The CGAL oracle: exact intersections whose answers follow from the construction, the
// judgement's tolerance rules on pairs built to sit on either side of them, its power to fail
// on corrupted RECODE results, and the generated pair suite judged pair by pair. Over 400 lines:
// each rule has pairs built on both sides of it.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "pair_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh_error.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/verify/cgal_oracle.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;
using Eigen::Vector3d;
using test::boxBetween;
using test::frameZ;

namespace {

core::TriangleMesh posed(const core::TriangleMesh& m, const Eigen::Matrix3d& rotation,
                         const Vector3d& offset) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation;
  t.translation() = offset;
  return core::transformed(m, t);
}

core::TriangleMesh moved(const core::TriangleMesh& m, const Vector3d& offset) {
  return posed(m, Eigen::Matrix3d::Identity(), offset);
}

// |x| + |y| + |z| <= r, faces counter-clockwise seen from outside.
core::TriangleMesh octahedron(double r) {
  core::TriangleMesh m;
  m.vertices = {{-r, 0, 0}, {r, 0, 0}, {0, -r, 0}, {0, r, 0}, {0, 0, -r}, {0, 0, r}};
  for (int octant = 0; octant < 8; ++octant) {
    const bool px = octant & 1, py = octant & 2, pz = octant & 4;
    const core::VertexIndex vx = px ? 1 : 0, vy = py ? 3 : 2, vz = pz ? 5 : 4;
    if ((px == py) == pz)
      m.triangles.push_back({vx, vy, vz});
    else
      m.triangles.push_back({vx, vz, vy});
  }
  return m;
}

// A cone of the given size with its apex exactly at the origin: pointing up (+z, body below)
// or down (body above). The flip y -> -y, z -> -z is exact.
core::TriangleMesh coneWithApexAtOrigin(double radius, double height, bool up) {
  const core::TriangleMesh cone = moved(core::makeCone(radius, height, 16), {0, 0, -height});
  if (up)
    return cone;
  return posed(cone, Vector3d(1.0, -1.0, -1.0).asDiagonal(), Vector3d::Zero());
}

bool sameBox(const core::Aabb& x, const Vector3d& lo, const Vector3d& hi) {
  return x.min == lo && x.max == hi;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("cgal oracle: unit boxes overlapping by exactly 0.5 along x") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({0.5, 0, 0}, {1.5, 1, 1});
  const verify::ExactIntersection e = verify::exactIntersection(a, b);
  CHECK(e.intersect);
  CHECK(e.volume == 0.5);
  CHECK(sameBox(e.box, {0.5, 0, 0}, {1, 1, 1}));
}

TEST_CASE("cgal oracle: boxes touching along a face intersect with volume 0") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({1, 0.25, -0.5}, {2, 0.75, 0.5});
  const verify::ExactIntersection e = verify::exactIntersection(a, b);
  CHECK(e.intersect);
  CHECK(e.volume == 0.0);
  CHECK(sameBox(e.box, {1, 0.25, 0}, {1, 0.75, 0.5}));
}

TEST_CASE("cgal oracle: boxes 1e-9 apart do not intersect") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({1 + 1e-9, 0, 0}, {2, 1, 1});
  const verify::ExactIntersection e = verify::exactIntersection(a, b);
  CHECK_FALSE(e.intersect);
  CHECK(e.volume == 0.0);
  CHECK(e.box.isEmpty());
  CHECK(e.boundaryPoints == 0);
}

TEST_CASE("cgal oracle: two cones meeting exactly tip on tip touch in one point") {
  const auto a = coneWithApexAtOrigin(0.5, 1.0, true);
  const auto b = coneWithApexAtOrigin(0.75, 1.5, false);
  const verify::ExactIntersection e = verify::exactIntersection(a, b);
  CHECK(e.intersect);
  CHECK(e.volume == 0.0);
  CHECK(sameBox(e.box, Vector3d::Zero(), Vector3d::Zero()));
  CHECK(e.boundaryPoints == 1);

  // Lifted by 1e-9 the down cone no longer reaches the up cone's apex.
  const verify::ExactIntersection apart = verify::exactIntersection(a, moved(b, {0, 0, 1e-9}));
  CHECK_FALSE(apart.intersect);
}

TEST_CASE("cgal oracle: a cone's apex resting on a box's face touches in one point") {
  const auto a = boxBetween({-1, -1, -1}, {1, 1, 0});
  const auto b = moved(coneWithApexAtOrigin(0.5, 1.0, false), {0.25, -0.125, 0});
  const verify::ExactIntersection e = verify::exactIntersection(a, b);
  CHECK(e.intersect);
  CHECK(e.volume == 0.0);
  CHECK(sameBox(e.box, {0.25, -0.125, 0}, {0.25, -0.125, 0}));
}

TEST_CASE("cgal oracle: a block inside another gives the inner block, either way round") {
  const auto outer = boxBetween({-2, -2, -2}, {2, 2, 2});
  const auto inner = boxBetween({-0.5, -0.25, 0.5}, {0, 0.75, 0.625});
  for (const bool swapped : {false, true}) {
    const verify::ExactIntersection e =
        swapped ? verify::exactIntersection(inner, outer) : verify::exactIntersection(outer, inner);
    CHECK(e.intersect);
    CHECK(e.volume == 0.5 * 1.0 * 0.125);
    CHECK(sameBox(e.box, {-0.5, -0.25, 0.5}, {0, 0.75, 0.625}));
  }
  // A curved inner block: the solid is the ellipsoid mesh itself, whose volume the divergence
  // theorem gives independently of CGAL.
  const auto ellipsoid = posed(
      core::makeEllipsoid(0.7, 0.4, 0.3, 16, 8),
      Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()).toRotationMatrix(), {0.1, -0.2, 0.3});
  const verify::ExactIntersection e = verify::exactIntersection(outer, ellipsoid);
  CHECK(e.intersect);
  CHECK(e.volume == Approx(core::signedVolume(ellipsoid)).epsilon(1e-12));
  const core::Aabb box = core::boundingBox(ellipsoid);
  CHECK(sameBox(e.box, box.min, box.max));
}

TEST_CASE("cgal oracle: a cube's corner cut by an octahedron is a simplex") {
  // [0, 2]^3 and |x| + |y| + |z| <= 2 meet in the simplex x, y, z >= 0, x + y + z <= 2, of
  // volume 2^3 / 6.
  const verify::ExactIntersection e =
      verify::exactIntersection(boxBetween({0, 0, 0}, {2, 2, 2}), octahedron(2.0));
  CHECK(e.intersect);
  CHECK(e.volume == Approx(8.0 / 6.0).epsilon(1e-15));
  CHECK(sameBox(e.box, {0, 0, 0}, {2, 2, 2}));
  CHECK(e.boundaryPoints >= 4);
}

TEST_CASE("cgal oracle: blocks that are not convex blocks are refused, naming the block") {
  const auto good = boxBetween({0, 0, 0}, {1, 1, 1});
  auto open = good;
  open.triangles.pop_back();
  auto notFinite = good;
  notFinite.vertices[3].x() = std::nan("");
  CHECK_THROWS_AS(verify::exactIntersection(open, good), core::MeshError);
  CHECK_THROWS_WITH(verify::exactIntersection(open, good), Catch::Contains("block A"));
  CHECK_THROWS_WITH(verify::exactIntersection(good, notFinite), Catch::Contains("block B"));
}

TEST_CASE("cgal judge: a clear overlap agrees; flipping RECODE's verdict is a disagreement") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = moved(a, {0.5, 0.25, 0.125});
  const core::FrameSpec frame = frameZ(-0.5, -0.5, 2.0, 2.0, 64, 64);
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  core::PairResult result = test::runPair(a, b, frame);
  REQUIRE(result.collide);
  const verify::CgalJudgement ok = verify::judgePair(exact, frame, a, b, result);
  CHECK(ok.verdict == verify::VerdictCheck::Agree);
  CHECK(ok.contactBoxInside);

  result.collide = false;
  const verify::CgalJudgement flipped = verify::judgePair(exact, frame, a, b, result);
  CHECK(flipped.verdict == verify::VerdictCheck::Disagree);
  CHECK(contains(flipped.reason, "pixel ("));
  CHECK(flipped.pixelX >= 0);
}

TEST_CASE("cgal judge: a contact box moved far away fails the box check") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = moved(a, {0.5, 0, 0});
  const core::FrameSpec frame = frameZ(-0.5, -0.5, 2.0, 2.0, 64, 64);
  core::PairResult result = test::runPair(a, b, frame);
  REQUIRE(result.collide);
  result.contact.box.min.x() += 10.0;
  result.contact.box.max.x() += 10.0;
  const verify::CgalJudgement j =
      verify::judgePair(verify::exactIntersection(a, b), frame, a, b, result);
  CHECK_FALSE(j.contactBoxInside);
  CHECK_FALSE(j.contactBoxExplained);
  CHECK(j.verdict == verify::VerdictCheck::Disagree);
}

TEST_CASE("cgal judge: faces touching within rounding may widen the contact box") {
  // Seen along x, B's face x = 1 - 1e-9 (y - 0.5) leans on A's face x = 1: they overlap (by
  // at most 5e-10) only for y > 0.5, but the device, whose depth step is 1.2e-7, sees them
  // touch over the whole face, y in [0, 1].
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  Eigen::Affine3d shear = Eigen::Affine3d::Identity();
  shear.linear()(0, 1) = -1e-9;
  shear.translation().x() = 0.5e-9;
  const auto b = core::transformed(boxBetween({1, 0, 0}, {2, 1, 1}), shear);
  core::FrameSpec frame = frameZ(-0.25, -0.25, 1.25, 1.25, 24, 24);
  frame.axis = core::ViewAxis::X;  // image plane (y, z)
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  REQUIRE(exact.intersect);
  CHECK(exact.box.min.y() == Approx(0.5).margin(1e-12));
  const core::PairResult result = test::runPair(a, b, frame);
  REQUIRE(result.collide);
  REQUIRE(result.contact.box.min.y() < 0.1);
  const verify::CgalJudgement j = verify::judgePair(exact, frame, a, b, result);
  CHECK_FALSE(j.contactBoxInside);
  CHECK(j.contactBoxExplained);
  CHECK(j.touchingPixelsOutside > 0);
  CHECK(j.verdict == verify::VerdictCheck::Agree);
}

TEST_CASE("cgal judge: a collision claimed between blocks far apart is a disagreement") {
  // B floats 1 above A along the view axis (z), so they share pixels but no depth.
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({0, 0, 2}, {1, 1, 3});
  const core::FrameSpec frame = frameZ(-0.5, -0.5, 1.5, 1.5, 32, 32);
  core::PairResult result =
      test::runPair(a, b, frame, core::MorMode::Full, /*contact=*/true, /*boxTest=*/false);
  REQUIRE_FALSE(result.collide);
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  REQUIRE_FALSE(exact.intersect);
  CHECK(verify::judgePair(exact, frame, a, b, result).verdict == verify::VerdictCheck::Agree);

  // Pixel (16, 16), centre (0.53125, 0.53125) on the plane, lies over both blocks (case 7, B
  // in front of A); claim interference there.
  result.caseMap.at(16, 16) = 3;
  result.collide = true;
  const verify::CgalJudgement overBoth = verify::judgePair(exact, frame, a, b, result);
  CHECK(overBoth.verdict == verify::VerdictCheck::Disagree);
  CHECK(overBoth.pixelX == 16);
  CHECK(overBoth.pixelY == 16);
  CHECK(contains(overBoth.reason, "depth steps"));

  // Pixel (1, 1), centre (-0.40625, -0.40625), lies over neither block: claim it instead.
  result.caseMap.at(16, 16) = 7;
  result.caseMap.at(1, 1) = 5;
  const verify::CgalJudgement overNone = verify::judgePair(exact, frame, a, b, result);
  CHECK(overNone.verdict == verify::VerdictCheck::Disagree);
  CHECK(contains(overNone.reason, "does not come within"));
}

TEST_CASE("cgal judge: an overlap between pixel centres is a resolution miss") {
  // Four pixels across [0, 4]: centres at 0.5, 1.5, 2.5, 3.5. A covers the centre 0.5, B the
  // centres 1.5 and 2.5, and they overlap in x in [1.1, 1.2], between centres.
  const auto a = boxBetween({0.2, 0.2, 0}, {1.2, 1.2, 1});
  const auto b = boxBetween({1.1, 0.2, 0.25}, {2.8, 1.2, 0.75});
  const core::FrameSpec frame = frameZ(0, 0, 4, 4, 4, 4);
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  REQUIRE(exact.intersect);
  CHECK(exact.volume == Approx(0.1 * 1.0 * 0.5).epsilon(1e-12));
  const core::PairResult result = test::runPair(a, b, frame);
  REQUIRE_FALSE(result.collide);
  const verify::CgalJudgement j = verify::judgePair(exact, frame, a, b, result);
  CHECK(j.verdict == verify::VerdictCheck::ResolutionMiss);
}

TEST_CASE("cgal judge: an overlap thinner than the depth tolerance is a resolution miss") {
  // Along the view axis B overlaps A's top by 1e-9, far under one depth step (2 / (2^24 - 1)).
  // Whichever verdict the device gives, the judge must accept it.
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({0, 0, 1 - 1e-9}, {1, 1, 2});
  const core::FrameSpec frame = frameZ(-0.25, -0.25, 1.25, 1.25, 24, 24);
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  REQUIRE(exact.intersect);
  core::PairResult result = test::runPair(a, b, frame);
  const verify::CgalJudgement actual = verify::judgePair(exact, frame, a, b, result);
  CHECK(actual.verdict != verify::VerdictCheck::Disagree);
  CHECK(actual.depthStep == Approx(2.0 / 16777215.0));
  // Had the device said apart, no pixel would have had to see a 1e-9 overlap.
  result.collide = false;
  const verify::CgalJudgement apart = verify::judgePair(exact, frame, a, b, result);
  CHECK(apart.verdict == verify::VerdictCheck::ResolutionMiss);
  CHECK(contains(apart.reason, "not above the tolerance"));
}

TEST_CASE("cgal judge: faces a hair apart along the view axis are an extra within rounding") {
  // B's bottom sits 1e-9 above A's top: both map to depth 0.5 (the float nearest to
  // 0.5 - 5e-10 is 0.5), so the device sees them touch; CGAL sees a gap.
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const auto b = boxBetween({0, 0, 1 + 1e-9}, {1, 1, 2});
  const core::FrameSpec frame = frameZ(-0.25, -0.25, 1.25, 1.25, 24, 24);
  const verify::ExactIntersection exact = verify::exactIntersection(a, b);
  REQUIRE_FALSE(exact.intersect);
  const core::PairResult result = test::runPair(a, b, frame);
  REQUIRE(result.collide);
  const verify::CgalJudgement j = verify::judgePair(exact, frame, a, b, result);
  // An extra contact, explained by rounding, is labelled an extra, not a miss.
  CHECK(j.verdict == verify::VerdictCheck::RoundingExtra);
  CHECK(verify::toString(j.verdict) == "extra within rounding");
  CHECK(contains(j.reason, "touch within rounding"));

  // 1e-3 apart (over 8000 depth steps) the same claimed collision is a disagreement.
  const auto far = boxBetween({0, 0, 1 + 1e-3}, {1, 1, 2});
  core::PairResult claimed =
      test::runPair(a, far, frame, core::MorMode::Min, /*contact=*/true, /*boxTest=*/false);
  REQUIRE_FALSE(claimed.collide);
  REQUIRE(claimed.caseMap.data.size() > 0);
  claimed.caseMap.data[claimed.caseMap.data.size() / 2] = 6;
  claimed.collide = true;
  const verify::CgalJudgement k =
      verify::judgePair(verify::exactIntersection(a, far), frame, a, far, claimed);
  CHECK(k.verdict == verify::VerdictCheck::Disagree);
}

TEST_CASE("cgal judge: an unusable depth range or a broken mesh is refused") {
  const auto a = boxBetween({0, 0, 0}, {1, 1, 1});
  const core::PairResult empty;  // depthMin == depthMax == 0
  CHECK_THROWS_AS(
      verify::judgePair(verify::exactIntersection(a, a), frameZ(0, 0, 1, 1, 8, 8), a, a, empty),
      std::invalid_argument);
  auto broken = a;
  broken.triangles[0][1] = 99;
  const core::FrameSpec frame = frameZ(0, 0, 1, 1, 8, 8);
  CHECK_THROWS_WITH(verify::judgePair(verify::exactIntersection(a, a), frame, a, broken,
                                      test::runPair(a, a, frame)),
                    Catch::Contains("block B") && Catch::Contains("vertex 99"));
}

TEST_CASE("cgal oracle: the generated pair suite has no disagreement") {
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  verify::CgalCounts counts;
  for (const verify::SuitePair& pair : suite) {
    INFO(pair.label);
    const verify::ExactIntersection exact = verify::exactIntersection(pair.a, pair.b);
    const core::PairResult result = test::runPair(pair.a, pair.b, pair.frame);
    const verify::CgalJudgement j = verify::judgePair(exact, pair.frame, pair.a, pair.b, result);
    counts.add(j);
    INFO(j.reason);
    CHECK(j.verdict != verify::VerdictCheck::Disagree);

    // What the construction says, where its gap dwarfs the rounding of the placement: the
    // touching configurations cycle through gaps -0.05, -1e-3, ..., 1e-3, 0.05 (round % 7),
    // just-separated pairs are at least 1e-6 apart, and an inner block lies wholly inside.
    const int round = std::stoi(pair.label.substr(pair.label.find('/') + 1, 3));
    switch (pair.configuration) {
      case verify::PairConfiguration::TipOnTip:
      case verify::PairConfiguration::TipOnFace:
      case verify::PairConfiguration::FaceOnFace:
      case verify::PairConfiguration::EdgeOnEdge:
        if (round % 7 <= 1)
          CHECK(exact.intersect);
        if (round % 7 >= 5)
          CHECK_FALSE(exact.intersect);
        break;
      case verify::PairConfiguration::JustSeparated:
        CHECK_FALSE(exact.intersect);
        break;
      case verify::PairConfiguration::Inside: {
        CHECK(exact.intersect);
        const double inner = std::min(core::signedVolume(pair.a), core::signedVolume(pair.b));
        CHECK(exact.volume == Approx(inner).epsilon(1e-9));
        break;
      }
      case verify::PairConfiguration::Random:
        break;
    }
  }
  CHECK(counts.pairs == static_cast<long long>(suite.size()));
  CHECK(counts.agree + counts.resolutionMisses + counts.roundingExtras + counts.disagree ==
        counts.pairs);
  CHECK(counts.disagree == 0);
}

TEST_CASE("cgal judge: the tolerance rules hold at every pixel of the suite's device results") {
  // The rules, checked against the device without CGAL: rule (b) applied to every colliding
  // pair as if the blocks were apart must explain each interfering pixel (an overlapping pixel
  // passes too); rule (a) applied with the verdict taken as apart must find a must-see pixel
  // only where the device did see interference, and none in pairs the device found apart. The
  // search box for rule (a) is the overlap of the blocks' boxes, which holds the intersection.
  const std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  long long mustSeeFound = 0;
  for (const verify::SuitePair& pair : suite) {
    INFO(pair.label);
    const core::PairResult result = test::runPair(pair.a, pair.b, pair.frame);
    core::Aabb overlap;
    const core::Aabb boxA = core::boundingBox(pair.a), boxB = core::boundingBox(pair.b);
    overlap.min = boxA.min.cwiseMax(boxB.min);
    overlap.max = boxA.max.cwiseMin(boxB.max);
    if (result.collide) {
      const verify::CgalJudgement asApart =
          verify::judgePair(verify::ExactIntersection{}, pair.frame, pair.a, pair.b, result);
      INFO(asApart.reason);
      CHECK(asApart.verdict == verify::VerdictCheck::RoundingExtra);
    }
    if (overlap.isEmpty())
      continue;
    verify::ExactIntersection superset;
    superset.intersect = true;
    superset.box = overlap;
    core::PairResult apart = result;
    apart.collide = false;
    const verify::CgalJudgement j = verify::judgePair(superset, pair.frame, pair.a, pair.b, apart);
    INFO(j.reason);
    if (!result.collide) {
      CHECK(j.verdict == verify::VerdictCheck::ResolutionMiss);
    } else if (j.verdict == verify::VerdictCheck::Disagree) {
      ++mustSeeFound;
      const raster::PixelRect& m = result.mor;
      REQUIRE(j.pixelX >= m.x0);
      REQUIRE(j.pixelX < m.x1);
      REQUIRE(j.pixelY >= m.y0);
      REQUIRE(j.pixelY < m.y1);
      CHECK(core::isInterfering(result.caseMap.at(j.pixelX, j.pixelY)));
    }
  }
  // Most colliding pairs overlap clearly, so rule (a) must have found must-see pixels.
  CHECK(mustSeeFound > 0);
}
