// The compute device's frame on the host, apart from Vulkan: its records and its work buffer's
// layout (tile_frame_records.hpp).

#include "tile_frame_records.hpp"

#include <algorithm>

namespace recode::backends::detail {

namespace {

using raster::PixelRect;

// Words a read of `pixels` in `form` fills in the read arena.
std::uint32_t readWords(TileReadForm form, long long pixels) {
  return static_cast<std::uint32_t>(form == TileReadForm::StencilBytes ? (pixels + 3) / 4 : pixels);
}

// The 8x8 blocks, from multiples of 8, that hold footprint `f`.
struct BlockGrid {
  explicit BlockGrid(const PixelRect& f)
      : x0(f.x0 & ~7),
        y0(f.y0 & ~7),
        width(static_cast<std::uint32_t>(((f.x1 - 1) >> 3) - (f.x0 >> 3) + 1)),
        height(static_cast<std::uint32_t>(((f.y1 - 1) >> 3) - (f.y0 >> 3) + 1)) {}
  std::int32_t x0;
  std::int32_t y0;
  std::uint32_t width;
  std::uint32_t height;
  [[nodiscard]] std::uint64_t blocks() const { return std::uint64_t{width} * height; }
};

// The resolve stage's ranges for one target's epochs that meet another (`shared`, in command
// order): each such epoch's footprint, with the later ones that meet it, which own the pixels
// they hold. Past kMostEpochsCompared every later one is listed, unsorted out.
void addResolveRanges(TileFrameRecords& r, const std::vector<std::uint32_t>& shared,
                      std::uint32_t target) {
  const bool compare = shared.size() <= kMostEpochsCompared;
  for (std::size_t i = 0; i < shared.size(); ++i) {
    const PixelRect f = rectOf(r.epochs[shared[i]].footprint);
    TileResolveRange range;
    putRect(f, range.rect);
    range.target = target;
    range.epoch = shared[i];
    range.firstLater = static_cast<std::uint32_t>(r.laterEpochs.size());
    for (std::size_t j = i + 1; j < shared.size(); ++j)
      if (!compare || !f.intersect(rectOf(r.epochs[shared[j]].footprint)).empty())
        r.laterEpochs.push_back(shared[j]);
    range.laterCount = static_cast<std::uint32_t>(r.laterEpochs.size()) - range.firstLater;
    range.firstPixel = r.resolvePixels;
    r.resolvePixels += static_cast<std::uint32_t>(f.area());
    r.resolveRanges.push_back(range);
  }
}

TileEpoch epochRecord(const EpochSpan& span, std::uint32_t target) {
  TileEpoch e;
  putRect(span.footprint, e.footprint);
  const BlockGrid grid(span.footprint);
  e.gridOrigin[0] = grid.x0;
  e.gridOrigin[1] = grid.y0;
  e.gridWidth = grid.width;
  e.gridHeight = grid.height;
  e.target = target;
  e.flags = (span.loads ? kTileEpochLoads : 0u) | (span.alone ? kTileEpochStores : 0u);
  return e;
}

}  // namespace

bool TileRecorded::empty() const {
  if (!vertexJobs.empty() || !boxBatches.empty())
    return false;
  return std::all_of(commands.begin(), commands.end(),
                     [](const std::vector<Pending>& c) { return c.empty(); });
}

std::vector<EpochSpan> withinFinalBudget(std::vector<EpochSpan> epochs, std::uint64_t finals,
                                         std::uint32_t mostLater) {
  std::uint64_t kept = 0;
  std::uint64_t shared = 0;
  for (const EpochSpan& e : epochs) {
    if (!e.alone) {
      kept += BlockGrid(e.footprint).blocks();
      ++shared;
    }
  }
  if (kept == 0 || (finals + kept <= kTileMostFinalJobs && shared <= std::uint64_t{mostLater} + 1))
    return epochs;
  EpochSpan all{epochs.front().begin, epochs.back().end, epochs.front().footprint, true, true};
  for (const EpochSpan& e : epochs)
    all.footprint = unite(all.footprint, e.footprint);
  return {all};
}

TileFrameRecords tileFrameRecords(const TileRecorded& recorded, const TileLoopBudgets& budgets) {
  TileFrameRecords r;
  for (const TileRecorded::Target& t : recorded.targets)
    r.targets.push_back({TileAddress::of(t.pixels), t.width, t.height});
  for (const TileVertices& job : recorded.vertexJobs) {
    r.windowFirst.push_back(r.windowVertices);
    r.windowVertices += job.vertexCount;
    r.transforms.insert(r.transforms.end(), job.transform.begin(), job.transform.end());
  }
  for (std::uint32_t t = 0; t < recorded.targets.size(); ++t) {
    const std::vector<TileRecorded::Pending>& list = recorded.commands[t];
    if (list.empty())
      continue;
    std::vector<EpochCommand> shapes;
    shapes.reserve(list.size());
    for (const TileRecorded::Pending& p : list)
      shapes.push_back(epochCommandOf(p.command, p.rect));
    std::vector<std::uint32_t> shared;  // this target's epochs that meet another
    for (const EpochSpan& span :
         withinFinalBudget(cutIntoEpochs(shapes), r.finals, budgets.resolveLater)) {
      TileEpoch e = epochRecord(span, t);
      const auto epochIndex = static_cast<std::uint32_t>(r.epochs.size());
      e.firstJob = r.jobs;
      e.firstFinal = r.finals;
      e.firstCommand = static_cast<std::uint32_t>(r.commands.size());
      const std::uint32_t firstTriangle = r.triangles;
      if (!span.alone) {
        r.finals += e.gridWidth * e.gridHeight;
        shared.push_back(epochIndex);
      }
      for (std::size_t c = span.begin; c < span.end; ++c) {
        const TileRecorded::Pending& p = list[c];
        TileCommand record = p.command;
        if (record.kind == TileCommandKind::Draw) {
          if (recorded.captured == std::make_pair(t, c))
            r.captured = std::make_pair(static_cast<std::uint32_t>(r.draws.size()), epochIndex);
          record.first = r.triangles;
          TileDrawSource d;
          d.vertices = TileAddress::of(p.vertices);  // a vertex job's: set once work is laid out
          r.drawVertexJob.push_back(p.vertexJob);
          d.indices = TileAddress::of(p.indices);
          d.firstTriangle = r.triangles;
          d.triangleCount = record.count;
          d.command = static_cast<std::uint32_t>(r.commands.size());
          d.epoch = epochIndex;
          r.draws.push_back(d);
          r.triangles += record.count;
          r.listCapacity += 4 * std::uint64_t{record.count} +
                            2 * std::uint64_t{e.gridWidth} * e.gridHeight + 4096;
        } else if (record.kind == TileCommandKind::Read) {
          record.arenaWord = r.arenaWords;
          const std::uint32_t words = readWords(record.readForm, p.rect.area());
          r.readCopies.push_back({p.destination, p.destinationOffset, r.arenaWords, words});
          r.arenaWords += words;
        }
        r.commands.push_back(record);
      }
      e.commandEnd = static_cast<std::uint32_t>(r.commands.size());
      // A job of the epoch lists at most every triangle of its draws.
      const std::uint64_t epochTriangles = r.triangles - firstTriangle;
      r.rasterRounds =
          std::max(r.rasterRounds,
                   tileRasterRounds(span.end - span.begin, epochTriangles, budgets.rasterWork));
      r.sortRounds = std::max(r.sortRounds, tileSortRounds(epochTriangles, budgets.sortWork));
      if (epochTriangles > 0)
        r.largestGrid = std::max<std::uint64_t>(r.largestGrid, BlockGrid(span.footprint).blocks());
      r.jobs += e.gridWidth * e.gridHeight;
      r.epochs.push_back(e);
    }
    addResolveRanges(r, shared, t);
  }
  for (const TileRecorded::BoxBatch& batch : recorded.boxBatches) {
    for (const TileBoxRequest& b : batch.blocks) {
      TileBoxJob job;
      job.local = TileAddress::of(b.local);
      job.vertexCount = b.vertexCount;
      job.pose = static_cast<std::uint32_t>(r.boxJobs.size());
      r.poses.insert(r.poses.end(), b.pose.begin(), b.pose.end());
      r.boxJobs.push_back(job);
    }
  }
  return r;
}

TileWorkLayout::TileWorkLayout(const TileFrameRecords& r)
    : entryCapacity(static_cast<std::uint32_t>(std::min(r.listCapacity, kTileMostListEntries))),
      triangleBytes(tileAligned(VkDeviceSize{r.triangles} * sizeof(TileSetUpTriangle) + 4)),
      jobBytes(tileAligned(VkDeviceSize{r.jobs} * 4 + 4)) {
  binEntriesAt = triangleBytes;
  offsetsAt = binEntriesAt + jobBytes;
  cursorsAt = offsetsAt + jobBytes;
  listsAt = cursorsAt + jobBytes;
  finalsAt = listsAt + tileAligned(VkDeviceSize{entryCapacity} * 4 + 4);
  windowsAt = finalsAt + tileAligned(VkDeviceSize{r.finals} * kTileJobPixelBytes + 4);
  arenaAt = windowsAt + tileAligned(VkDeviceSize{r.windowVertices} * kTileWindowVertexBytes + 4);
  boxesAt = arenaAt + tileAligned(VkDeviceSize{r.arenaWords} * 4 + 4);
  // The rounds' records, needed only where a stage may take more than one round; the
  // progress, counters and rounds' arguments are zeroed each frame.
  const VkDeviceSize rasterProgress =
      r.rasterRounds > 1 ? VkDeviceSize{r.jobs} * 2 * kTileRasterProgressBytes : 16;
  const VkDeviceSize sortProgress =
      r.sortRounds > 1 ? VkDeviceSize{r.jobs} * kTileSortProgressBytes : 16;
  const VkDeviceSize carry = r.rasterRounds > 1 ? VkDeviceSize{r.jobs} * kTileJobPixelBytes : 16;
  progressAt = boxesAt + tileAligned(VkDeviceSize{r.boxJobs.size()} * kTileBoxBytes + 8);
  sortProgressAt = progressAt + tileAligned(rasterProgress);
  countersAt = sortProgressAt + tileAligned(sortProgress);
  rasterArgsAt = countersAt + tileAligned(kTileCounters * 4);
  sortArgsAt = rasterArgsAt + tileAligned(VkDeviceSize{r.rasterRounds + 1} * kTileRoundArgsBytes);
  carryAt = sortArgsAt + tileAligned(VkDeviceSize{r.sortRounds + 1} * kTileRoundArgsBytes);
  bytes = carryAt + tileAligned(carry);
}

void placeVertexJobs(TileFrameRecords& r, const std::vector<TileVertices>& vertexJobs,
                     const TileWorkLayout& layout, VkDeviceAddress workAddress) {
  for (std::size_t j = 0; j < vertexJobs.size(); ++j) {
    TileVertexJob job;
    job.local = TileAddress::of(vertexJobs[j].local);
    job.windows = TileAddress::of(workAddress + layout.windowsAt +
                                  VkDeviceSize{r.windowFirst[j]} * kTileWindowVertexBytes);
    job.firstVertex = r.windowFirst[j];
    job.vertexCount = vertexJobs[j].vertexCount;
    job.transform = static_cast<std::uint32_t>(j);
    r.vertexJobs.push_back(job);
  }
  for (std::size_t d = 0; d < r.draws.size(); ++d)
    if (r.drawVertexJob[d] >= 0)
      r.draws[d].vertices = r.vertexJobs[static_cast<std::size_t>(r.drawVertexJob[d])].windows;
}

}  // namespace recode::backends::detail
