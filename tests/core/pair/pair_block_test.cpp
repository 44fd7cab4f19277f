// Blocks with triangle hierarchies (pair_block.hpp) are refused exactly as bare meshes are: a
// vertex the view cannot map gives the same error, before anything is drawn, whether or not
// the block could have been drawn culled; and a hierarchy of another mesh is refused.

#include <catch2/catch.hpp>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "pair_test_support.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "recode/raster/command_stream.hpp"

using namespace recode;
using test::boxBetween;
using test::frameZ;

namespace {

// The message collidePair throws, and how many commands reached the device first.
std::pair<std::string, std::size_t> refusal(const core::PairBlock& a, const core::PairBlock& b,
                                            const core::FrameSpec& frame) {
  raster::CpuDevice inner(frame.width, frame.height);
  raster::RecordingDevice recorder(inner);
  core::PairRequest request;
  request.frame = frame;
  try {
    (void)core::collidePair(recorder, a, b, request);
  } catch (const std::invalid_argument& e) {
    return {e.what(), recorder.stream().commands.size()};
  }
  return {"(nothing thrown)", recorder.stream().commands.size()};
}

}  // namespace

TEST_CASE("pair blocks: a vertex beyond the fixed-point range is refused as for a bare mesh") {
  // 64 pixels over [-1, 1]: 32 pixels per unit, so x = 2000 maps to about 64,000 pixels.
  const core::FrameSpec frame = frameZ(-1, -1, 1, 1, 64, 64);
  const auto near = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  auto far = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  far.vertices[3].x() = 2000.0;
  const auto bare = refusal(core::PairBlock(near), core::PairBlock(far), frame);
  CHECK_THAT(bare.first, Catch::Contains("beyond the +-32768 pixel range"));
  CHECK(bare.second == 0);
  for (const bool farFirst : {false, true}) {
    const core::PairBlock a = core::PairBlock::withHierarchy(farFirst ? far : near);
    const core::PairBlock b = core::PairBlock::withHierarchy(farFirst ? near : far);
    const auto culled = refusal(a, b, frame);
    const auto whole = refusal(core::PairBlock(farFirst ? far : near),
                               core::PairBlock(farFirst ? near : far), frame);
    CHECK(culled == whole);
    CHECK(culled.first == bare.first);
  }
}

TEST_CASE("pair blocks: a vertex that is not finite is refused as for a bare mesh") {
  const core::FrameSpec frame = frameZ(-1, -1, 1, 1, 64, 64);
  const auto near = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  auto bad = near;
  bad.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  const core::PairBlock culledBad = core::PairBlock::withHierarchy(bad);
  CHECK_FALSE(culledBad.drawable());
  CHECK(refusal(core::PairBlock::withHierarchy(near), culledBad, frame) ==
        refusal(core::PairBlock(near), core::PairBlock(bad), frame));
}

TEST_CASE("pair blocks: a hierarchy over another number of triangles is refused") {
  const auto box = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  auto fewer = box;
  fewer.triangles.pop_back();
  CHECK_THROWS_WITH(core::PairBlock(box, std::make_shared<const core::TriangleBvh>(fewer),
                                    Eigen::Isometry3d::Identity()),
                    Catch::Contains("the hierarchy has 11 triangles but the mesh has 12"));
}

TEST_CASE("pair blocks: an object-space mesh of the block's own counts is kept and offered") {
  // A box (8 vertices, 12 triangles) with its own object-space mesh and identity pose: the
  // counts match (24 coordinates, 36 indices), so the block keeps it; one triangle fewer is
  // refused.
  const auto box = boxBetween({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  const auto bvh = std::make_shared<const core::TriangleBvh>(box);
  const auto local = std::make_shared<const core::ObjectSpaceMesh>(box);
  CHECK(local->xyz.size() == 24);
  CHECK(local->indices.size() == 36);
  const core::PairBlock block(box, bvh, Eigen::Isometry3d::Identity(), local);
  CHECK(block.objectSpaceMesh() == local);
  auto fewer = box;
  fewer.triangles.pop_back();
  CHECK_THROWS_WITH(
      core::PairBlock(box, bvh, Eigen::Isometry3d::Identity(),
                      std::make_shared<const core::ObjectSpaceMesh>(fewer)),
      Catch::Contains("the object-space mesh has 8 vertices and 11 triangles but the mesh has 8 "
                      "and 12"));
}

TEST_CASE("pair blocks: an object-space mesh of a mesh without triangles has no indices") {
  core::TriangleMesh points;
  points.vertices = {{1, 2, 3}, {4, 5, 6}};
  const core::ObjectSpaceMesh local(points);
  CHECK(local.xyz == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(local.indices.empty());
}
