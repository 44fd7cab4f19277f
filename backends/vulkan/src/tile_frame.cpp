// TileFrame: a frame's commands kept on the host, cut into epochs and run as one job list just
// before the recording is submitted (tile_frame.hpp).

#include "tile_frame.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "tile_frame_budgets.hpp"
#include "tile_frame_records.hpp"
#include "vulkan_compute_pipelines.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends::detail {

namespace {

using raster::PixelRect;

static_assert(kTileRoundArgsBytes == sizeof(VkDispatchIndirectCommand));

// The timestamps around the groups of stages that TransferCounters::stageUs times, in the order
// of its kStageNames: a group's time runs from its own timestamp to the next.
enum class TileTimer : std::uint32_t {
  Vertex = 0,   // the box and vertex stages
  SetUp = 1,    // the set-up stage
  Binning = 2,  // count, scan, scatter, sort
  Raster = 3,   // the raster stage's rounds
  Reads = 4,    // the resolve stage, the reads' and boxes' copies, the counters' copy
  End = 5,
};
static_assert(static_cast<std::size_t>(TileTimer::End) == raster::TransferCounters::kStages);
constexpr std::uint32_t kTimestamps = static_cast<std::uint32_t>(TileTimer::End) + 1;

// The interface's state as the shaders read it (tile_frame_layout.hpp's packing).
void putState(const raster::RenderState& s, TileCommand& c) {
  const auto bits = [](auto value) { return static_cast<std::uint32_t>(value); };
  c.tests = bits(s.depthFunc) | (s.depthWrite ? kTileDepthWriteBit : 0u) |
            (bits(s.stencilFunc) << kTileStencilFuncShift) | (bits(s.cull) << kTileCullShift);
  c.stencil = bits(s.stencilRef) | (bits(s.stencilValueMask) << kTileValueMaskShift) |
              (bits(s.stencilWriteMask) << kTileWriteMaskShift);
  const auto ops = [&](const raster::StencilOps& o) {
    return bits(o.stencilFail) | (bits(o.depthFail) << kTileDepthFailShift) |
           (bits(o.depthPass) << kTileDepthPassShift);
  };
  c.ops = ops(s.frontOps) | (ops(s.backOps) << kTileBackOpsShift);
}

// Jobs a workgroup of the raster stage runs: eight side by side, one an invocation's eight
// columns (tile_raster.comp). One job an invocation: its loop budget is its own.
constexpr std::uint32_t kRasterJobsPerGroup = 8;

// Jobs the serial scan (tile_scan_serial.comp, for CPU drivers) takes: llvmpipe ends a shader's
// loops after 65,535 iterations in all, so more go to the workgroup's scan, whose invocations
// each loop over a 256th of them.
constexpr std::uint32_t kMostSerialScanJobs = 32768;

}  // namespace

struct TileFrame::Impl {
  VulkanContext& context;
  CommandRecorder& recorder;
  const TilePipelines& pipelines;
  const TileLoopBudgets budgets;  // within the driver's loop limit (tile_frame_budgets.hpp)

  TileRecorded recorded;
  std::map<std::uint64_t, int> vertexJobOfKey;       // content key -> vertex job, this frame
  std::function<void(TileDrawCapture)> captureSink;  // where recorded.captured goes

  DeviceBuffer work;  // the frame's set-up triangles, bins, job finals, windows, reads, boxes
  VkQueryPool queries = VK_NULL_HANDLE;
  bool timed = false;      // whether the submission being run wrote the timestamps
  HostBuffer countersOut;  // the stages' counters after the run (kTileCounters words)
  // What the submission being run asked of the stages: raster job columns, sorted jobs.
  struct Expected {
    std::uint64_t columns = 0;
    std::uint64_t sorted = 0;
  };
  std::optional<Expected> expected;

  Impl(VulkanContext& c, CommandRecorder& r, const TilePipelines& p)
      : context(c), recorder(r), pipelines(p), budgets(tileLoopBudgets(c.loopLimit())) {
    countersOut = context.createHostBuffer(kTileCounters * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (context.timestamps()) {
      VkQueryPoolCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
      info.queryType = VK_QUERY_TYPE_TIMESTAMP;
      info.queryCount = kTimestamps;
      vkCheck(vkCreateQueryPool(context.device(), &info, nullptr, &queries), "vkCreateQueryPool");
    }
  }

  TileRecorded::Pending& add(std::uint32_t target, TileCommandKind kind, const PixelRect& rect) {
    if (target >= recorded.targets.size() || !recorded.targets[target].live)
      throw std::logic_error("TileFrame: a command for a framebuffer it does not hold");
    recorder.open();
    TileRecorded::Pending& p = recorded.commands[target].emplace_back();
    p.command.kind = kind;
    p.command.target = target;
    p.rect = rect;
    putRect(rect, p.command.rect);
    return p;
  }

  // `bytes` of host data where the stages can read them: at least one word, so that an empty
  // record array still binds.
  template <class T>
  TileBuffer uploaded(TileBinding binding, const std::vector<T>& values) {
    const std::size_t bytes = values.size() * sizeof(T);
    static constexpr std::uint32_t kNothing[4] = {0, 0, 0, 0};
    const CommandRecorder::Staged staged = bytes == 0 ? recorder.upload(kNothing, sizeof kNothing)
                                                      : recorder.upload(values.data(), bytes);
    return {binding, staged.buffer, staged.offset, std::max<VkDeviceSize>(bytes, sizeof kNothing)};
  }

  void reserveWork(VkDeviceSize bytes) {
    if (work.buffer != VK_NULL_HANDLE && work.size >= bytes)
      return;
    // Every earlier submission has run (finish waits), so nothing uses the old buffer.
    context.destroyDeviceBuffer(work);
    work = context.createDeviceBuffer(
        std::max<VkDeviceSize>(bytes, 1 << 20),
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
            VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  }

  void timestamp(VkCommandBuffer cmd, TileTimer timer) {
    if (timed)
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries,
                          static_cast<std::uint32_t>(timer));
  }

  void run(VkCommandBuffer cmd);
  [[nodiscard]] TileFrameConstants constantsOf(const TileFrameRecords& r,
                                               const TileWorkLayout& layout) const;
  [[nodiscard]] std::vector<TileBuffer> buffersOf(const TileFrameRecords& r,
                                                  const TileWorkLayout& layout);
  void recordStages(VkCommandBuffer cmd, const TileFrameRecords& r, const TileWorkLayout& layout);
  void recordCopies(VkCommandBuffer cmd, const TileFrameRecords& r, const TileWorkLayout& layout);
  void clearRecorded();
  void recordCheck(VkCommandBuffer cmd, const TileFrameRecords& r, const TileWorkLayout& layout);
  void recordCapture(VkCommandBuffer cmd, const TileFrameRecords& r, const TileWorkLayout& layout);
  void readTimes();
  void checkCounters();
};

// Runs everything recorded since the last submission: see tile_frame.hpp for the stages.
void TileFrame::Impl::run(VkCommandBuffer cmd) {
  timed = false;
  if (recorded.empty())
    return;
  TileFrameRecords r = tileFrameRecords(recorded, budgets);
  if (r.jobs > budgets.scanJobs) {
    clearRecorded();
    throw std::runtime_error("vulkan-compute: a frame of " + std::to_string(r.jobs) +
                             " jobs (8x8 blocks of its epochs) passes the " +
                             std::to_string(budgets.scanJobs) +
                             " the scan stage takes within this driver's loop limit of " +
                             std::to_string(context.loopLimit()) + " iterations an invocation");
  }
  const TileWorkLayout layout(r);
  reserveWork(layout.bytes);
  placeVertexJobs(r, recorded.vertexJobs, layout, context.address(work.buffer));
  recordStages(cmd, r, layout);
  recordCopies(cmd, r, layout);
  recordCheck(cmd, r, layout);
  if (r.captured)
    recordCapture(cmd, r, layout);
  computeBarrier(cmd);
  timestamp(cmd, TileTimer::End);
  clearRecorded();
}

void TileFrame::Impl::clearRecorded() {
  for (std::vector<TileRecorded::Pending>& list : recorded.commands)
    list.clear();
  recorded.vertexJobs.clear();
  vertexJobOfKey.clear();
  recorded.boxBatches.clear();
  recorded.captured.reset();
  captureSink = nullptr;
}

// The push constants every stage of the frame starts from.
TileFrameConstants TileFrame::Impl::constantsOf(const TileFrameRecords& r,
                                                const TileWorkLayout& layout) const {
  TileFrameConstants k;
  k.vertexCount = r.windowVertices;
  k.vertexJobs = static_cast<std::uint32_t>(r.vertexJobs.size());
  k.triangleCount = r.triangles;
  k.drawCount = static_cast<std::uint32_t>(r.draws.size());
  k.jobCount = r.jobs;
  k.epochCount = static_cast<std::uint32_t>(r.epochs.size());
  k.entryCapacity = layout.entryCapacity;
  k.resolvePixels = r.resolvePixels;
  k.resolveRanges = static_cast<std::uint32_t>(r.resolveRanges.size());
  k.boxJobs = static_cast<std::uint32_t>(r.boxJobs.size());
  k.rasterBudget = r.rasterRounds > 1 ? budgets.rasterWork : kTileUnbounded;
  k.sortBudget = r.sortRounds > 1 ? budgets.sortWork : kTileUnbounded;
  k.scatterChunks = tileScatterChunks(r.largestGrid, budgets.scatterBlocks);
  k.scatterBlocks = k.scatterChunks > 1 ? budgets.scatterBlocks : kTileUnbounded;
  return k;
}

// Every buffer the stages bind, one a binding: the records uploaded, and the work buffer's
// regions (each from its start to the next region's).
std::vector<TileBuffer> TileFrame::Impl::buffersOf(const TileFrameRecords& r,
                                                   const TileWorkLayout& layout) {
  const VkBuffer w = work.buffer;
  const auto region = [w](TileBinding binding, VkDeviceSize at, VkDeviceSize end) {
    return TileBuffer{binding, w, at, end - at};
  };
  return {
      uploaded(TileBinding::Targets, r.targets),
      uploaded(TileBinding::Epochs, r.epochs),
      uploaded(TileBinding::Commands, r.commands),
      uploaded(TileBinding::Draws, r.draws),
      uploaded(TileBinding::VertexJobs, r.vertexJobs),
      uploaded(TileBinding::Transforms, r.transforms),
      uploaded(TileBinding::ResolveRanges, r.resolveRanges),
      uploaded(TileBinding::LaterEpochs, r.laterEpochs),
      uploaded(TileBinding::BoxJobs, r.boxJobs),
      uploaded(TileBinding::Poses, r.poses),
      region(TileBinding::Triangles, 0, layout.triangleBytes),
      region(TileBinding::BinEntries, layout.binEntriesAt, layout.binEntriesAt + layout.jobBytes),
      region(TileBinding::BinOffsets, layout.offsetsAt, layout.offsetsAt + layout.jobBytes),
      region(TileBinding::BinCursors, layout.cursorsAt, layout.cursorsAt + layout.jobBytes),
      region(TileBinding::Lists, layout.listsAt, layout.finalsAt),
      region(TileBinding::JobFinal, layout.finalsAt, layout.windowsAt),
      region(TileBinding::ReadArena, layout.arenaAt, layout.boxesAt),
      region(TileBinding::Boxes, layout.boxesAt, layout.progressAt),
      region(TileBinding::RasterProgress, layout.progressAt, layout.sortProgressAt),
      region(TileBinding::SortProgress, layout.sortProgressAt, layout.countersAt),
      region(TileBinding::Counters, layout.countersAt, layout.rasterArgsAt),
      region(TileBinding::RasterRoundArgs, layout.rasterArgsAt, layout.sortArgsAt),
      region(TileBinding::SortRoundArgs, layout.sortArgsAt, layout.carryAt),
      region(TileBinding::Carry, layout.carryAt, layout.bytes),
  };
}

namespace {

// The frame's stages as they are recorded: each a call that binds its pipeline, pushes the
// constants as they are then and dispatches (nothing when the stage has nothing to do), on top of
// the buffers pushed once for the frame; it counts the dispatches.
class StageRecorder {
 public:
  StageRecorder(VkCommandBuffer cmd, const TilePipelines& pipelines, TileFrameConstants& constants,
                VkBuffer work)
      : cmd_(cmd), pipelines_(pipelines), k_(constants), work_(work) {}

  // `count` invocations of a 64-wide stage that reads linearInvocation().
  void linear(VkPipeline pipeline, std::uint64_t count) { groups(pipeline, (count + 63) / 64); }

  // `groups` workgroups of a stage that reads linearWorkgroup().
  void groups(VkPipeline pipeline, std::uint64_t groups) {
    if (groups == 0)
      return;
    const auto [perRow, rows] = TilePipelines::groupGrid(groups);
    pipelines_.dispatch(cmd_, pipeline, k_, perRow, rows);
    ++dispatches_;
  }

  // A stage in `rounds`: the first of `groups` workgroups, each later one an indirect dispatch
  // whose size the round before writes at `argsAt` in the work buffer (zero unless some job
  // stopped at its budget), a barrier after each.
  void inRounds(VkPipeline pipeline, std::uint64_t groups, std::uint32_t rounds,
                VkDeviceSize argsAt) {
    if (groups == 0)
      return;
    std::tie(k_.roundGroupsX, k_.roundGroupsY) = TilePipelines::groupGrid(groups);
    for (k_.round = 0; k_.round < rounds; ++k_.round) {
      if (k_.round == 0)
        pipelines_.dispatch(cmd_, pipeline, k_, k_.roundGroupsX, k_.roundGroupsY);
      else
        pipelines_.dispatchIndirect(cmd_, pipeline, k_, work_,
                                    argsAt + VkDeviceSize{k_.round} * kTileRoundArgsBytes);
      ++dispatches_;
      computeBarrier(cmd_);
    }
    k_.round = 0;
  }

  [[nodiscard]] long long dispatches() const { return dispatches_; }

 private:
  VkCommandBuffer cmd_;
  const TilePipelines& pipelines_;
  TileFrameConstants& k_;
  VkBuffer work_;
  long long dispatches_ = 0;
};

}  // namespace

// The stages in order, with a compute barrier between dependent ones and a timestamp before each
// group of them (TileTimer).
void TileFrame::Impl::recordStages(VkCommandBuffer cmd, const TileFrameRecords& r,
                                   const TileWorkLayout& layout) {
  TileFrameConstants k = constantsOf(r, layout);
  const VkBuffer w = work.buffer;
  timed = queries != VK_NULL_HANDLE;
  if (timed)
    vkCmdResetQueryPool(cmd, queries, 0, kTimestamps);
  pipelines.pushBuffers(cmd, buffersOf(r, layout));
  StageRecorder stage(cmd, pipelines, k, w);
  // What the devices recorded before (uploads, framebuffer fills) is visible to the stages.
  computeBarrier(cmd);
  vkCmdFillBuffer(cmd, w, layout.binEntriesAt, layout.jobBytes, 0);
  vkCmdFillBuffer(cmd, w, layout.arenaAt, layout.boxesAt - layout.arenaAt, 0);  // ORed into
  vkCmdFillBuffer(cmd, w, layout.progressAt, layout.carryAt - layout.progressAt, 0);
  computeBarrier(cmd);
  timestamp(cmd, TileTimer::Vertex);
  stage.groups(pipelines.box, r.boxJobs.size());  // a workgroup a block
  stage.linear(pipelines.vertex, r.windowVertices);
  computeBarrier(cmd);
  timestamp(cmd, TileTimer::SetUp);
  stage.linear(pipelines.setup, r.triangles);
  computeBarrier(cmd);
  timestamp(cmd, TileTimer::Binning);
  if (r.triangles > 0) {
    // The scatter counts (binPass 0), the scan places the lists, the scatter fills them, the
    // sort puts each in order.
    const std::uint64_t scatterInvocations = std::uint64_t{r.triangles} * k.scatterChunks;
    stage.linear(pipelines.scatter, scatterInvocations);
    computeBarrier(cmd);
    const bool serial = context.cpuDriver() && r.jobs <= kMostSerialScanJobs;
    stage.groups(serial ? pipelines.scanSerial : pipelines.scan, 1);
    computeBarrier(cmd);
    k.binPass = 1;
    stage.linear(pipelines.scatter, scatterInvocations);
    computeBarrier(cmd);
    stage.inRounds(pipelines.sort, (std::uint64_t{r.jobs} + 63) / 64, r.sortRounds,
                   layout.sortArgsAt);  // a job an invocation
  }
  timestamp(cmd, TileTimer::Raster);
  stage.inRounds(pipelines.raster,
                 (std::uint64_t{r.jobs} + kRasterJobsPerGroup - 1) / kRasterJobsPerGroup,
                 r.rasterRounds, layout.rasterArgsAt);
  timestamp(cmd, TileTimer::Reads);
  stage.linear(pipelines.resolve, r.resolvePixels);
  raster::TransferCounters counted;
  counted.dispatches = stage.dispatches();
  recorder.count(counted);
}

// The reads and boxes to their destinations (the summaries' dispatch comes after, with its own
// barrier), one copy command a destination buffer.
void TileFrame::Impl::recordCopies(VkCommandBuffer cmd, const TileFrameRecords& r,
                                   const TileWorkLayout& layout) {
  std::map<VkBuffer, std::vector<VkBufferCopy>> copies;
  for (const TileFrameRecords::ReadCopy& read : r.readCopies)
    if (read.words > 0)
      copies[read.destination].push_back({layout.arenaAt + VkDeviceSize{read.firstWord} * 4,
                                          read.offset, VkDeviceSize{read.words} * 4});
  VkDeviceSize box = 0;
  for (const TileRecorded::BoxBatch& batch : recorded.boxBatches) {
    if (!batch.blocks.empty())
      copies[batch.destination].push_back({layout.boxesAt + box * kTileBoxBytes, batch.offset,
                                           batch.blocks.size() * kTileBoxBytes});
    box += batch.blocks.size();
  }
  for (const auto& [destination, regions] : copies)
    vkCmdCopyBuffer(cmd, work.buffer, destination, static_cast<std::uint32_t>(regions.size()),
                    regions.data());
}

// The stages' counters copied to the frame's own host memory, compared after the run (in
// checkCounters, before any read-back is delivered) with what the frame asked of them: a stage
// that did less than all of its work (a loop a driver ended early, a round too few) is an error
// that names it, never a smaller answer.
void TileFrame::Impl::recordCheck(VkCommandBuffer cmd, const TileFrameRecords& r,
                                  const TileWorkLayout& layout) {
  computeBarrier(cmd);  // the resolve stage counts too
  expected = Expected{std::uint64_t{r.jobs} * kTileJobLanes, r.triangles > 0 ? r.jobs : 0};
  const VkBufferCopy back{layout.countersAt, 0, kTileCounters * 4};
  vkCmdCopyBuffer(cmd, work.buffer, countersOut.buffer, 1, &back);
}

void TileFrame::Impl::checkCounters() {
  if (!expected)
    return;
  const Expected asked = *expected;
  expected.reset();
  std::array<std::uint32_t, kTileCounters> counted{};
  std::memcpy(counted.data(), countersOut.mapped, sizeof counted);
  checkTileCounters(counted, asked.columns, asked.sorted, context.loopLimit());
}

// The captured draw's set-up triangles, its epoch's job lists and its window vertices, copied
// back and handed to the capture's sink.
void TileFrame::Impl::recordCapture(VkCommandBuffer cmd, const TileFrameRecords& r,
                                    const TileWorkLayout& layout) {
  const auto [drawIndex, epochIndex] = *r.captured;
  const TileDrawSource d = r.draws[drawIndex];
  const TileEpoch e = r.epochs[epochIndex];
  const int job = r.drawVertexJob[drawIndex];
  const VkDeviceSize bytes = layout.finalsAt;  // triangles, bins and lists
  const VkDeviceSize windowBytes =
      job >= 0 ? VkDeviceSize{r.vertexJobs[static_cast<std::size_t>(job)].vertexCount} *
                     kTileWindowVertexBytes
               : 0;
  const CommandRecorder::Staged out = recorder.results(
      bytes + windowBytes,
      [d, e, bytes, layout, windowBytes, sink = std::move(captureSink)](const std::uint8_t* data) {
        const auto word = [&](VkDeviceSize at) {
          std::uint32_t v = 0;
          std::memcpy(&v, data + at, 4);
          return v;
        };
        TileDrawCapture c;
        c.firstTriangle = d.firstTriangle;
        c.triangles.resize(d.triangleCount);
        std::memcpy(c.triangles.data(),
                    data + VkDeviceSize{d.firstTriangle} * sizeof(TileSetUpTriangle),
                    c.triangles.size() * sizeof(TileSetUpTriangle));
        c.gridOrigin[0] = e.gridOrigin[0];
        c.gridOrigin[1] = e.gridOrigin[1];
        c.gridWidth = e.gridWidth;
        c.gridHeight = e.gridHeight;
        for (std::uint32_t b = 0; b < e.gridWidth * e.gridHeight; ++b) {
          const VkDeviceSize at = VkDeviceSize{e.firstJob + b} * 4;
          const std::uint32_t n = word(layout.binEntriesAt + at);
          const std::uint32_t first = word(layout.offsetsAt + at);
          const bool overflowed = VkDeviceSize{first} + n > layout.entryCapacity;
          std::vector<std::uint32_t> list;
          for (std::uint32_t i = 0; i < n && !overflowed; ++i)
            list.push_back(word(layout.listsAt + (VkDeviceSize{first} + i) * 4));
          c.overflowed.push_back(overflowed);
          c.jobLists.push_back(std::move(list));
        }
        c.windowVertices.resize(windowBytes / 4);
        std::memcpy(c.windowVertices.data(), data + bytes, windowBytes);
        sink(std::move(c));
      });
  const VkBufferCopy back{0, out.offset, bytes};
  vkCmdCopyBuffer(cmd, work.buffer, out.buffer, 1, &back);
  if (job >= 0) {
    const VkDeviceSize windowsAt =
        layout.windowsAt +
        VkDeviceSize{r.windowFirst[static_cast<std::size_t>(job)]} * kTileWindowVertexBytes;
    const VkBufferCopy windowCopy{windowsAt, out.offset + bytes, windowBytes};
    vkCmdCopyBuffer(cmd, work.buffer, out.buffer, 1, &windowCopy);
  }
}

void TileFrame::Impl::readTimes() {
  if (!timed)
    return;
  timed = false;
  std::array<std::uint64_t, kTimestamps> ticks{};
  if (vkGetQueryPoolResults(context.device(), queries, 0, kTimestamps, sizeof ticks, ticks.data(),
                            sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT) != VK_SUCCESS)
    return;  // not ready cannot happen after the fence; a lost device is reported elsewhere
  raster::TransferCounters counted;
  for (std::size_t s = 0; s < raster::TransferCounters::kStages; ++s)
    counted.stageUs[s] =
        static_cast<double>(ticks[s + 1] - ticks[s]) * context.timestampPeriodNs() / 1000.0;
  recorder.count(counted);
}

TileFrame::TileFrame(VulkanContext& context, CommandRecorder& recorder,
                     const TilePipelines& pipelines)
    : impl_(std::make_unique<Impl>(context, recorder, pipelines)) {
  Impl* impl = impl_.get();
  recorder.addSubmitHooks(
      0, [impl](VkCommandBuffer cmd) { impl->run(cmd); },
      [impl] {
        impl->readTimes();
        impl->checkCounters();
      });
}

TileFrame::~TileFrame() = default;

std::uint32_t TileFrame::addTarget(VkBuffer framebuffer, int width, int height) {
  Impl& f = *impl_;
  TileRecorded::Target target{true, f.context.address(framebuffer),
                              static_cast<std::uint32_t>(width),
                              static_cast<std::uint32_t>(height)};
  TileRecorded& r = f.recorded;
  for (std::uint32_t t = 0; t < r.targets.size(); ++t) {
    if (!r.targets[t].live && r.commands[t].empty()) {
      r.targets[t] = target;
      return t;
    }
  }
  r.targets.push_back(target);
  r.commands.emplace_back();
  return static_cast<std::uint32_t>(r.targets.size() - 1);
}

void TileFrame::removeTarget(std::uint32_t target) {
  impl_->recorded.targets.at(target).live = false;
  impl_->recorded.commands.at(target).clear();
}

void TileFrame::clearDepth(std::uint32_t target, const PixelRect& scissor, std::uint32_t q) {
  impl_->add(target, TileCommandKind::ClearDepth, scissor).command.value = q;
}

void TileFrame::clearStencil(std::uint32_t target, const PixelRect& scissor, std::uint8_t value,
                             std::uint8_t writeMask) {
  TileRecorded::Pending& p = impl_->add(target, TileCommandKind::ClearStencil, scissor);
  p.command.value = value;
  p.command.clearMask = writeMask;
}

void TileFrame::draw(std::uint32_t target, const raster::RenderState& state,
                     const TileVertices& vertices, VkDeviceAddress indices,
                     std::uint32_t triangles) {
  Impl& f = *impl_;
  TileRecorded::Pending& p = f.add(target, TileCommandKind::Draw, state.scissor);
  putState(state, p.command);
  p.command.count = triangles;
  p.indices = indices;
  if (vertices.window != 0) {
    p.vertices = vertices.window;
    return;
  }
  if (vertices.contentKey != 0) {
    if (const auto found = f.vertexJobOfKey.find(vertices.contentKey);
        found != f.vertexJobOfKey.end()) {
      p.vertexJob = found->second;
      return;
    }
  }
  p.vertexJob = static_cast<int>(f.recorded.vertexJobs.size());
  f.recorded.vertexJobs.push_back(vertices);
  if (vertices.contentKey != 0)
    f.vertexJobOfKey[vertices.contentKey] = p.vertexJob;
}

void TileFrame::read(std::uint32_t target, const PixelRect& rect, TileReadForm form,
                     VkBuffer destination, VkDeviceSize offset) {
  TileRecorded::Pending& p = impl_->add(target, TileCommandKind::Read, rect);
  p.command.readForm = form;
  p.destination = destination;
  p.destinationOffset = offset;
}

void TileFrame::boxes(const std::vector<BoxRequest>& blocks, VkBuffer destination,
                      VkDeviceSize offset) {
  for (const BoxRequest& b : blocks)
    if (b.vertexCount > impl_->budgets.boxVertices)
      throw std::runtime_error(
          "vulkan-compute: a block of " + std::to_string(b.vertexCount) + " vertices passes the " +
          std::to_string(impl_->budgets.boxVertices) +
          " the box stage takes within this driver's loop limit of " +
          std::to_string(impl_->context.loopLimit()) + " iterations an invocation");
  impl_->recorder.open();
  impl_->recorded.boxBatches.push_back({blocks, destination, offset});
}

void TileFrame::captureLastDraw(std::uint32_t target, std::function<void(TileDrawCapture)> sink) {
  Impl& f = *impl_;
  const std::vector<TileRecorded::Pending>& list = f.recorded.commands.at(target);
  for (std::size_t c = list.size(); c > 0; --c) {
    if (list[c - 1].command.kind == TileCommandKind::Draw) {
      f.recorded.captured = std::make_pair(target, c - 1);
      f.captureSink = std::move(sink);
      return;
    }
  }
}

TileFrame& tileFrame() {
  // Leaked, as the context and the recorder.
  static TileFrame* made =
      new TileFrame(VulkanContext::instance(ShaderArithmetic::Native64),
                    sharedRecorder(ShaderArithmetic::Native64), tilePipelines());
  return *made;
}

}  // namespace recode::backends::detail
