// Culled draws change no bit: collidePair with blocks that carry triangle hierarchies on a
// CpuDevice (which then draws only the triangles near its scissor) against the same pair drawn
// whole through the device seam's default drawMesh (every triangle, the command stream as
// recorded), over the generated suite: the results, the case maps, the contact regions and
// both devices' whole buffers, bit for bit; and the culled side must really have drawn fewer
// triangles, so the comparison is not between two full draws.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <memory>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;

namespace {

// Forwards everything to a CpuDevice but keeps the seam's default drawMesh: every block is
// drawn whole with drawTriangles, as on GL, Vulkan or a recording.
using WholeDrawDevice = raster::ForwardingDevice;

bool sameBits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

bool samePoints(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& y) {
  if (x.size() != y.size())
    return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!sameBits(x[i][k], y[i][k]))
        return false;
  return true;
}

void requireSameResult(const core::PairResult& full, const core::PairResult& culled) {
  CHECK(full.collide == culled.collide);
  CHECK(full.boxesOverlap == culled.boxesOverlap);
  CHECK(full.mor == culled.mor);
  CHECK(full.caseCounts == culled.caseCounts);
  CHECK(full.caseMap.rect == culled.caseMap.rect);
  CHECK(full.caseMap.data == culled.caseMap.data);
  CHECK(full.contactRect == culled.contactRect);
  CHECK(samePoints(full.contact.points, culled.contact.points));
  CHECK(full.contact.collapsedPixels == culled.contact.collapsedPixels);
  CHECK(sameBits(full.contact.maxDepth, culled.contact.maxDepth));
  CHECK(sameBits(full.depthMin, culled.depthMin));
  CHECK(sameBits(full.depthMax, culled.depthMax));
}

// The suite's pairs at `width`, each with every MOR mode; returns the triangles the culled
// side drew and the whole side drew, summed.
std::pair<std::uint64_t, std::uint64_t> compareSuite(int width, int count) {
  verify::PairSuiteOptions options;
  options.width = width;
  options.count = count;
  std::uint64_t culledTriangles = 0, wholeTriangles = 0;
  for (const verify::SuitePair& p : verify::generatePairSuite(options)) {
    const core::PairBlock blockA = core::PairBlock::withHierarchy(p.a);
    const core::PairBlock blockB = core::PairBlock::withHierarchy(p.b);
    for (const core::MorMode mor : {core::MorMode::Min, core::MorMode::Max, core::MorMode::Full}) {
      INFO(p.label << " at width " << width << ", mor " << core::toString(mor));
      core::PairRequest request;
      request.frame = p.frame;
      request.mor = mor;
      raster::CpuDevice wholeInner(p.frame.width, p.frame.height);
      WholeDrawDevice whole(wholeInner);
      raster::CpuDevice culled(p.frame.width, p.frame.height);
      const core::PairResult r0 = core::collidePair(whole, p.a, p.b, request);
      const core::PairResult r1 = core::collidePair(culled, blockA, blockB, request);
      requireSameResult(r0, r1);
      CHECK(std::equal(wholeInner.depthBuffer().begin(), wholeInner.depthBuffer().end(),
                       culled.depthBuffer().begin(), culled.depthBuffer().end()));
      CHECK(std::equal(wholeInner.stencilBuffer().begin(), wholeInner.stencilBuffer().end(),
                       culled.stencilBuffer().begin(), culled.stencilBuffer().end()));
      culledTriangles += culled.counters().trianglesSubmitted;
      wholeTriangles += wholeInner.counters().trianglesSubmitted;
    }
  }
  return {culledTriangles, wholeTriangles};
}

}  // namespace

TEST_CASE("culled draws: the generated suite at width 64 gives the whole draws' bits") {
  // 168 pairs: 24 of each configuration (the whole 504 take minutes on a busy CI machine).
  const auto [culled, whole] = compareSuite(64, 168);
  INFO("triangles drawn: culled " << culled << ", whole " << whole);
  CHECK(culled < whole);
}

TEST_CASE("culled draws: blocks posed over hierarchies of their local meshes give the same bits") {
  // As a run draws its leaves: the world mesh made from the local one by a pose, the hierarchy
  // over the local mesh, so its boxes are moved by the pose at every query.
  verify::PairSuiteOptions options;
  options.count = 56;
  std::uint64_t culledTriangles = 0, wholeTriangles = 0;
  int index = 0;
  for (const verify::SuitePair& p : verify::generatePairSuite(options)) {
    ++index;
    const Eigen::Isometry3d pose =
        Eigen::Translation3d(0.3 * index, -0.7, 1.1) *
        Eigen::AngleAxisd(0.37 * index, Eigen::Vector3d(1, 2, 3).normalized());
    const core::TriangleMesh worldA = core::transformed(p.a, pose);
    const core::TriangleMesh worldB = core::transformed(p.b, pose);
    const core::PairBlock blockA(worldA, std::make_shared<const core::TriangleBvh>(p.a), pose);
    const core::PairBlock blockB(worldB, std::make_shared<const core::TriangleBvh>(p.b), pose);
    core::Aabb bounds = blockA.box();
    bounds.extend(blockB.box());
    core::PairRequest request;
    request.frame = core::resolveFrame(core::ViewSpec{}, bounds, {96, {}, {}});
    INFO(p.label << " posed");
    raster::CpuDevice wholeInner(request.frame.width, request.frame.height);
    WholeDrawDevice whole(wholeInner);
    raster::CpuDevice culled(request.frame.width, request.frame.height);
    requireSameResult(core::collidePair(whole, worldA, worldB, request),
                      core::collidePair(culled, blockA, blockB, request));
    CHECK(std::equal(wholeInner.depthBuffer().begin(), wholeInner.depthBuffer().end(),
                     culled.depthBuffer().begin(), culled.depthBuffer().end()));
    CHECK(std::equal(wholeInner.stencilBuffer().begin(), wholeInner.stencilBuffer().end(),
                     culled.stencilBuffer().begin(), culled.stencilBuffer().end()));
    culledTriangles += culled.counters().trianglesSubmitted;
    wholeTriangles += wholeInner.counters().trianglesSubmitted;
  }
  INFO("triangles drawn: culled " << culledTriangles << ", whole " << wholeTriangles);
  CHECK(culledTriangles < wholeTriangles);
}

TEST_CASE("culled draws: a part of the suite at width 512 gives the whole draws' bits") {
  const auto [culled, whole] = compareSuite(512, 14);
  INFO("triangles drawn: culled " << culled << ", whole " << whole);
  CHECK(culled < whole);
}

TEST_CASE("culled draws: dense touching spheres under a thin MOR give the whole draws' bits") {
  // The benchmark's case (docs/benchmarks.md, "A pair's cost and its meshes") at 256 x 128:
  // thousands of sub-pixel triangles near a 2-pixel column. The culled side must produce the
  // very same fragments from far fewer triangles.
  const core::TriangleMesh a = core::makeSphere(1.0, 256, 128);
  core::TriangleMesh b = a;
  for (Eigen::Vector3d& p : b.vertices)
    p.x() += 1.98;
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::PairRequest request;
  request.frame = core::resolveFrame(core::ViewSpec{}, bounds, {512, 512, {}});
  raster::CpuDevice wholeInner(512, 512);
  WholeDrawDevice whole(wholeInner);
  raster::CpuDevice culled(512, 512);
  const core::PairResult r0 = core::collidePair(whole, a, b, request);
  const core::PairResult r1 = core::collidePair(culled, core::PairBlock::withHierarchy(a),
                                                core::PairBlock::withHierarchy(b), request);
  REQUIRE(r0.collide);
  REQUIRE(r0.mor.width() <= 3);
  requireSameResult(r0, r1);
  CHECK(std::equal(wholeInner.depthBuffer().begin(), wholeInner.depthBuffer().end(),
                   culled.depthBuffer().begin(), culled.depthBuffer().end()));
  CHECK(std::equal(wholeInner.stencilBuffer().begin(), wholeInner.stencilBuffer().end(),
                   culled.stencilBuffer().begin(), culled.stencilBuffer().end()));
  CHECK(culled.counters().fragments == wholeInner.counters().fragments);
  CHECK(culled.counters().fragments > 0);
  CHECK(culled.counters().trianglesSubmitted < wholeInner.counters().trianglesSubmitted);
}
