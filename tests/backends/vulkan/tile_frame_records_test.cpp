// The compute device's frame records (backends/vulkan/src/tile_frame_records.hpp): commands,
// draws and reads numbered in command order, epochs and their jobs, the resolve stage's ranges,
// the fallback to one epoch, and the work buffer's regions. Vulkan-free: the expected values
// follow from the rules in the header and in docs/backends.md ("A frame is one job list").

#include <catch2/catch.hpp>

#include <cstdint>
#include <utility>
#include <vector>

#include "tile_frame_records.hpp"

using namespace recode::backends::detail;
using recode::raster::PixelRect;

namespace {

TileRecorded withTargets(std::uint32_t count) {
  TileRecorded f;
  for (std::uint32_t t = 0; t < count; ++t) {
    f.targets.push_back({true, 0x10000 * (t + 1), 64, 64});
    f.commands.emplace_back();
  }
  return f;
}

TileRecorded::Pending& add(TileRecorded& f, std::uint32_t target, TileCommandKind kind,
                           const PixelRect& rect) {
  TileRecorded::Pending& p = f.commands[target].emplace_back();
  p.command.kind = kind;
  p.command.target = target;
  p.rect = rect;
  putRect(rect, p.command.rect);
  return p;
}

// A pair test's start: depth and every stencil bit cleared over `r`.
void reset(TileRecorded& f, std::uint32_t target, const PixelRect& r) {
  add(f, target, TileCommandKind::ClearDepth, r);
  add(f, target, TileCommandKind::ClearStencil, r).command.clearMask = 0xFF;
}

void draw(TileRecorded& f, std::uint32_t target, const PixelRect& scissor,
          std::uint32_t triangles) {
  add(f, target, TileCommandKind::Draw, scissor).command.count = triangles;
}

void read(TileRecorded& f, std::uint32_t target, const PixelRect& r, TileReadForm form) {
  add(f, target, TileCommandKind::Read, r).command.readForm = form;
}

std::vector<std::uint32_t> laterOf(const TileFrameRecords& r, const TileResolveRange& range) {
  return {r.laterEpochs.begin() + range.firstLater,
          r.laterEpochs.begin() + range.firstLater + range.laterCount};
}

EpochSpan span(std::size_t begin, std::size_t end, const PixelRect& footprint, bool alone) {
  return {begin, end, footprint, false, alone};
}

}  // namespace

TEST_CASE("a frame's records number its targets' commands, draws and reads in command order",
          "[tile-records]") {
  TileRecorded f = withTargets(2);
  reset(f, 0, {0, 0, 16, 16});
  draw(f, 0, {0, 0, 16, 16}, 10);
  read(f, 0, {0, 0, 10, 1}, TileReadForm::StencilBytes);  // 10 bytes: 3 words
  reset(f, 0, {32, 32, 48, 48});
  draw(f, 0, {32, 32, 48, 48}, 5);
  read(f, 0, {32, 32, 34, 34}, TileReadForm::DepthWords);  // 4 words
  draw(f, 1, {3, 3, 20, 12}, 7);                           // no reset: starts from the framebuffer
  f.captured = std::make_pair(0u, std::size_t{6});         // target 0's second draw
  const TileFrameRecords r = tileFrameRecords(f, tileLoopBudgets(0));

  REQUIRE(r.targets.size() == 2);
  CHECK(r.targets[1].pixels.low == 0x20000);
  REQUIRE(r.commands.size() == 9);
  REQUIRE(r.epochs.size() == 3);
  // Target 0's pair tests: epochs of their own, from their clears, alone (they store).
  CHECK(r.epochs[0].firstCommand == 0);
  CHECK(r.epochs[0].commandEnd == 4);
  CHECK(r.epochs[0].flags == kTileEpochStores);
  CHECK(r.epochs[0].gridWidth == 2);
  CHECK(r.epochs[0].gridHeight == 2);
  CHECK(r.epochs[0].firstJob == 0);
  CHECK(r.epochs[1].firstCommand == 4);
  CHECK(r.epochs[1].commandEnd == 8);
  CHECK(r.epochs[1].gridOrigin[0] == 32);
  CHECK(r.epochs[1].gridOrigin[1] == 32);
  CHECK(r.epochs[1].firstJob == 4);
  // Target 1's draw: the blocks of its scissor from multiples of 8 (x 0-23, y 0-15: 3 x 2).
  CHECK(r.epochs[2].target == 1);
  CHECK(r.epochs[2].flags == (kTileEpochLoads | kTileEpochStores));
  CHECK(r.epochs[2].gridOrigin[0] == 0);
  CHECK(r.epochs[2].gridWidth == 3);
  CHECK(r.epochs[2].gridHeight == 2);
  CHECK(r.epochs[2].firstJob == 8);
  CHECK(r.jobs == 14);
  CHECK(r.finals == 0);
  CHECK(r.resolveRanges.empty());
  // Draws: their triangles numbered across the frame, each pointing at its command and epoch.
  CHECK(r.triangles == 22);
  REQUIRE(r.draws.size() == 3);
  CHECK(r.draws[1].firstTriangle == 10);
  CHECK(r.draws[1].triangleCount == 5);
  CHECK(r.draws[1].command == 6);
  CHECK(r.draws[1].epoch == 1);
  CHECK(r.draws[2].firstTriangle == 15);
  CHECK(r.draws[2].command == 8);
  CHECK(r.commands[6].first == 10);
  CHECK(r.commands[8].first == 15);
  // Reads: their words one after another in the arena.
  CHECK(r.commands[3].arenaWord == 0);
  CHECK(r.commands[7].arenaWord == 3);
  REQUIRE(r.readCopies.size() == 2);
  CHECK(r.readCopies[0].words == 3);
  CHECK(r.readCopies[1].firstWord == 3);
  CHECK(r.readCopies[1].words == 4);
  CHECK(r.arenaWords == 7);
  // For each draw, 4 entries a triangle, 2 a job of its epoch and 4,096.
  CHECK(r.listCapacity == (40 + 8 + 4096) + (20 + 8 + 4096) + (28 + 12 + 4096));
  CHECK(r.captured == std::make_pair(1u, 1u));
}

TEST_CASE(
    "epochs that meet another leave their pixels to the resolve stage, each range listing "
    "the later epochs that meet it",
    "[tile-records]") {
  TileRecorded f = withTargets(1);
  const PixelRect a{0, 0, 16, 16}, b{8, 8, 24, 24}, c{20, 20, 28, 28};  // b meets a and c
  for (const PixelRect& r : {a, b, c}) {
    reset(f, 0, r);
    draw(f, 0, r, 1);
  }
  const TileFrameRecords r = tileFrameRecords(f, tileLoopBudgets(0));
  REQUIRE(r.epochs.size() == 3);
  for (const TileEpoch& e : r.epochs)
    CHECK(e.flags == 0u);  // neither loads nor stores
  // Each keeps its 2 x 2 jobs' pixels, one after another.
  CHECK(r.epochs[1].firstFinal == 4);
  CHECK(r.epochs[2].firstFinal == 8);
  CHECK(r.finals == 12);
  REQUIRE(r.resolveRanges.size() == 3);
  CHECK(laterOf(r, r.resolveRanges[0]) == std::vector<std::uint32_t>{1});
  CHECK(laterOf(r, r.resolveRanges[1]) == std::vector<std::uint32_t>{2});
  CHECK(laterOf(r, r.resolveRanges[2]).empty());
  CHECK(r.resolveRanges[1].epoch == 1);
  CHECK(r.resolveRanges[1].firstPixel == 256);
  CHECK(r.resolveRanges[2].firstPixel == 512);
  CHECK(r.resolvePixels == 576);
}

TEST_CASE(
    "a target's epochs become one that loads and stores when they would keep too many "
    "jobs or meet too many others",
    "[tile-records]") {
  // Three shared epochs of 2 x 2 jobs each, and one alone.
  const std::vector<EpochSpan> epochs = {
      span(0, 3, {0, 0, 16, 16}, false), span(3, 6, {8, 8, 24, 24}, false),
      span(6, 9, {20, 20, 28, 28}, false), span(9, 12, {40, 40, 48, 48}, true)};
  const auto merged = [](const std::vector<EpochSpan>& out) {
    return out.size() == 1 && out[0].begin == 0 && out[0].end == 12 && out[0].loads &&
           out[0].alone && out[0].footprint == PixelRect{0, 0, 48, 48};
  };
  CHECK(withinFinalBudget(epochs, 0, kTileUnbounded).size() == 4);
  CHECK(withinFinalBudget(epochs, kTileMostFinalJobs - 12, kTileUnbounded).size() == 4);
  CHECK(merged(withinFinalBudget(epochs, kTileMostFinalJobs - 11, kTileUnbounded)));
  // A resolve invocation compares a pixel's range with at most `mostLater` later ones.
  CHECK(withinFinalBudget(epochs, 0, 2).size() == 4);
  CHECK(merged(withinFinalBudget(epochs, 0, 1)));
  // Epochs that are all alone keep nothing: never merged.
  const std::vector<EpochSpan> alone = {span(0, 3, {0, 0, 8, 8}, true),
                                        span(3, 6, {16, 16, 24, 24}, true)};
  CHECK(withinFinalBudget(alone, kTileMostFinalJobs, 0).size() == 2);
}

TEST_CASE(
    "the work buffer's regions follow one another from multiples of 256, each as large as "
    "the frame needs",
    "[tile-records]") {
  TileFrameRecords r;
  r.triangles = 3;
  r.jobs = 5;
  r.finals = 2;
  r.windowVertices = 7;
  r.arenaWords = 9;
  r.boxJobs.resize(1);
  r.rasterRounds = 3;
  r.sortRounds = 2;
  r.listCapacity = 10;
  const TileWorkLayout w(r);
  CHECK(w.entryCapacity == 10);
  // Each region from its start to the next one's, and the least it must hold.
  const std::vector<std::pair<VkDeviceSize, VkDeviceSize>> regions = {
      {0, 3 * sizeof(TileSetUpTriangle)},
      {w.binEntriesAt, 5 * 4},
      {w.offsetsAt, 5 * 4},
      {w.cursorsAt, 5 * 4},
      {w.listsAt, 10 * 4},
      {w.finalsAt, 2 * kTileJobPixelBytes},
      {w.windowsAt, 7 * kTileWindowVertexBytes},
      {w.arenaAt, 9 * 4},
      {w.boxesAt, kTileBoxBytes},
      {w.progressAt, 5 * 2 * kTileRasterProgressBytes},  // two sets: a round reads one
      {w.sortProgressAt, 5 * kTileSortProgressBytes},
      {w.countersAt, kTileCounters * 4},
      {w.rasterArgsAt, 4 * kTileRoundArgsBytes},  // rounds + 1
      {w.sortArgsAt, 3 * kTileRoundArgsBytes},
      {w.carryAt, 5 * kTileJobPixelBytes},
      {w.bytes, 0}};
  for (std::size_t k = 0; k + 1 < regions.size(); ++k) {
    INFO("region " << k);
    CHECK(regions[k].first % kTileBindAlignment == 0);
    CHECK(regions[k + 1].first >= regions[k].first + regions[k].second);
  }
  CHECK(w.triangleBytes == w.binEntriesAt);
  CHECK(w.jobBytes == w.offsetsAt - w.binEntriesAt);
  // An empty frame's regions hold a word each still: every one is bound, and a binding's range
  // may not be empty.
  const TileWorkLayout empty{TileFrameRecords{}};
  const std::vector<VkDeviceSize> starts = {0,
                                            empty.binEntriesAt,
                                            empty.offsetsAt,
                                            empty.cursorsAt,
                                            empty.listsAt,
                                            empty.finalsAt,
                                            empty.windowsAt,
                                            empty.arenaAt,
                                            empty.boxesAt,
                                            empty.progressAt,
                                            empty.sortProgressAt,
                                            empty.countersAt,
                                            empty.rasterArgsAt,
                                            empty.sortArgsAt,
                                            empty.carryAt,
                                            empty.bytes};
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    INFO("region " << k);
    CHECK(starts[k + 1] > starts[k]);
  }
  // The lists never hold more than 2^27 entries, however many the draws would give them.
  r.listCapacity = std::uint64_t{1} << 30;
  CHECK(TileWorkLayout(r).entryCapacity == kTileMostListEntries);
}

TEST_CASE(
    "posed draws take their window vertices from their vertex job's place in the work "
    "buffer",
    "[tile-records]") {
  TileRecorded f = withTargets(1);
  TileVertices first, second;
  first.local = 0x5000;
  first.vertexCount = 3;
  second.local = 0x6000;
  second.vertexCount = 4;
  f.vertexJobs = {first, second};
  draw(f, 0, {0, 0, 8, 8}, 1);
  f.commands[0].back().vertexJob = 1;
  draw(f, 0, {0, 0, 8, 8}, 1);
  f.commands[0].back().vertices = 0x7000;  // window vertices given
  TileFrameRecords r = tileFrameRecords(f, tileLoopBudgets(0));
  CHECK(r.windowVertices == 7);
  const TileWorkLayout w(r);
  const VkDeviceAddress work = 0x100000;
  placeVertexJobs(r, f.vertexJobs, w, work);
  REQUIRE(r.vertexJobs.size() == 2);
  CHECK(r.vertexJobs[1].firstVertex == 3);
  CHECK(r.vertexJobs[1].local.low == 0x6000);
  CHECK(r.vertexJobs[1].transform == 1);
  const VkDeviceAddress secondWindows = work + w.windowsAt + 3 * kTileWindowVertexBytes;
  CHECK(r.draws[0].vertices.low == static_cast<std::uint32_t>(secondWindows));
  CHECK(r.draws[1].vertices.low == 0x7000);
}
