// TileFrame: a frame's commands kept on the host, cut into epochs and run as one job list just
// before the recording is submitted (tile_frame.hpp).

#include "tile_frame.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "tile_frame_epochs.hpp"
#include "vulkan_compute_pipelines.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends::detail {

namespace {

using raster::PixelRect;

// Offsets of the regions a dispatch binds: the largest minStorageBufferOffsetAlignment the
// specification allows, so no device needs asking.
constexpr VkDeviceSize kBindAlignment = 256;

VkDeviceSize aligned(VkDeviceSize bytes) {
  return (bytes + kBindAlignment - 1) / kBindAlignment * kBindAlignment;
}

// The timestamps around the stages (kStages + 1 of them).
constexpr std::uint32_t kTimestamps = raster::TransferCounters::kStages + 1;

// The interface's state as the shaders read it (tile_common.glsl's Command words).
void putState(const raster::RenderState& s, TileCommand& c) {
  const auto bits = [](auto value) { return static_cast<std::uint32_t>(value); };
  c.tests = bits(s.depthFunc) | (s.depthWrite ? 8u : 0u) | (bits(s.stencilFunc) << 4) |
            (bits(s.cull) << 7);
  c.stencil =
      bits(s.stencilRef) | (bits(s.stencilValueMask) << 8) | (bits(s.stencilWriteMask) << 16);
  const auto ops = [&](const raster::StencilOps& o) {
    return bits(o.stencilFail) | (bits(o.depthFail) << 3) | (bits(o.depthPass) << 6);
  };
  c.ops = ops(s.frontOps) | (ops(s.backOps) << 9);
}

void putRect(const PixelRect& r, TileCommand& c) {
  c.rect[0] = r.x0;
  c.rect[1] = r.y0;
  c.rect[2] = r.x1;
  c.rect[3] = r.y1;
}

// Words a read of `pixels` in `form` fills in the read arena.
std::uint32_t readWords(TileReadForm form, long long pixels) {
  return static_cast<std::uint32_t>(form == TileReadForm::StencilBytes ? (pixels + 3) / 4 : pixels);
}

}  // namespace

struct TileFrame::Impl {
  VulkanContext& context;
  CommandRecorder& recorder;
  const TilePipelines& pipelines;

  struct Target {
    bool live = false;
    VkDeviceAddress pixels = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
  };
  std::vector<Target> targets;

  // A command as recorded: what the shaders read, and what the host still needs.
  struct Pending {
    TileCommand command;
    PixelRect rect;
    // A draw's sources: window vertices by address, or a vertex job's (vertexJob >= 0).
    VkDeviceAddress vertices = 0;
    int vertexJob = -1;
    VkDeviceAddress indices = 0;
    // A read's destination.
    VkBuffer destination = VK_NULL_HANDLE;
    VkDeviceSize destinationOffset = 0;
  };
  std::vector<std::vector<Pending>> commands;  // by target

  struct VertexJob {
    TileVertices source;
  };
  std::vector<VertexJob> vertexJobs;
  std::map<std::uint64_t, int> vertexJobOfKey;  // content key -> vertex job, this frame

  struct BoxBatch {
    std::vector<BoxRequest> blocks;
    VkBuffer destination = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
  };
  std::vector<BoxBatch> boxBatches;

  struct Capture {
    std::uint32_t target = 0;
    std::size_t command = 0;
    std::function<void(TileDrawCapture)> sink;
  };
  std::optional<Capture> capture;

  DeviceBuffer work;  // the frame's set-up triangles, bins, job finals, windows, reads, boxes
  VkQueryPool queries = VK_NULL_HANDLE;
  bool timed = false;  // whether the submission being run wrote the timestamps

  Impl(VulkanContext& c, CommandRecorder& r, const TilePipelines& p)
      : context(c), recorder(r), pipelines(p) {
    if (context.timestamps()) {
      VkQueryPoolCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
      info.queryType = VK_QUERY_TYPE_TIMESTAMP;
      info.queryCount = kTimestamps;
      vkCheck(vkCreateQueryPool(context.device(), &info, nullptr, &queries), "vkCreateQueryPool");
    }
  }

  bool empty() const {
    if (!vertexJobs.empty() || !boxBatches.empty())
      return false;
    return std::all_of(commands.begin(), commands.end(),
                       [](const std::vector<Pending>& c) { return c.empty(); });
  }

  Pending& add(std::uint32_t target, TileCommandKind kind, const PixelRect& rect) {
    if (target >= targets.size() || !targets[target].live)
      throw std::logic_error("TileFrame: a command for a framebuffer it does not hold");
    recorder.open();
    Pending& p = commands[target].emplace_back();
    p.command.kind = kind;
    p.command.target = target;
    p.rect = rect;
    putRect(rect, p.command);
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
    work = context.createDeviceBuffer(std::max<VkDeviceSize>(bytes, 1 << 20),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  }

  void timestamp(VkCommandBuffer cmd, std::uint32_t k) {
    if (timed)
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, k);
  }

  void run(VkCommandBuffer cmd);
  void readTimes();
};

// Runs everything recorded since the last submission: see tile_frame.hpp for the stages.
void TileFrame::Impl::run(VkCommandBuffer cmd) {
  timed = false;
  if (empty())
    return;
  // The frame's records, target by target, each target's commands cut into epochs.
  std::vector<TileTarget> targetRecords(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t)
    targetRecords[t] = {TileAddress::of(targets[t].pixels), targets[t].width, targets[t].height};
  std::vector<TileCommand> commandRecords;
  std::vector<TileEpoch> epochRecords;
  std::vector<TileDrawSource> drawRecords;
  std::vector<TileResolveRange> resolveRecords;
  struct ReadCopy {
    VkBuffer destination;
    VkDeviceSize offset;
    std::uint32_t firstWord;
    std::uint32_t words;
  };
  std::vector<ReadCopy> readCopies;
  std::uint32_t triangles = 0;
  std::uint32_t jobs = 0;
  std::uint32_t arenaWords = 0;
  std::uint32_t resolvePixels = 0;
  // The captured draw's place in the frame's numbering.
  std::optional<std::pair<std::uint32_t, std::uint32_t>> captured;  // (draw record, epoch)
  // Posed draws' window vertices: vertex job k's from windowFirst[k] (in vertices).
  std::vector<std::uint32_t> windowFirst;
  std::uint32_t windowVertices = 0;
  for (const VertexJob& job : vertexJobs) {
    windowFirst.push_back(windowVertices);
    windowVertices += job.source.vertexCount;
  }
  for (std::uint32_t t = 0; t < targets.size(); ++t) {
    const std::vector<Pending>& list = commands[t];
    if (list.empty())
      continue;
    std::vector<EpochCommand> shapes;
    shapes.reserve(list.size());
    for (const Pending& p : list)
      shapes.push_back(epochCommandOf(p.command, p.rect));
    const std::vector<EpochSpan> spans = cutIntoEpochs(shapes);
    const auto firstEpoch = static_cast<std::uint32_t>(epochRecords.size());
    PixelRect resolveRect;
    bool resolves = false;
    for (const EpochSpan& span : spans) {
      TileEpoch e;
      const PixelRect& f = span.footprint;
      e.footprint[0] = f.x0;
      e.footprint[1] = f.y0;
      e.footprint[2] = f.x1;
      e.footprint[3] = f.y1;
      e.gridOrigin[0] = f.x0 & ~7;
      e.gridOrigin[1] = f.y0 & ~7;
      e.gridWidth = static_cast<std::uint32_t>(((f.x1 - 1) >> 3) - (f.x0 >> 3) + 1);
      e.gridHeight = static_cast<std::uint32_t>(((f.y1 - 1) >> 3) - (f.y0 >> 3) + 1);
      e.target = t;
      e.firstJob = jobs;
      e.firstCommand = static_cast<std::uint32_t>(commandRecords.size());
      e.flags = (span.loads ? kTileEpochLoads : 0u) | (span.alone ? kTileEpochStores : 0u);
      if (!span.alone) {
        resolveRect = resolves ? unite(resolveRect, f) : f;
        resolves = true;
      }
      const auto epochIndex = static_cast<std::uint32_t>(epochRecords.size());
      for (std::size_t c = span.begin; c < span.end; ++c) {
        const Pending& p = list[c];
        TileCommand record = p.command;
        if (record.kind == TileCommandKind::Draw) {
          const auto drawIndex = static_cast<std::uint32_t>(drawRecords.size());
          if (capture && capture->target == t && capture->command == c)
            captured = std::make_pair(drawIndex, epochIndex);
          record.first = triangles;
          TileDrawSource d;
          d.vertices = TileAddress::of(p.vertices);
          d.indices = TileAddress::of(p.indices);
          d.firstTriangle = triangles;
          d.triangleCount = record.count;
          d.command = static_cast<std::uint32_t>(commandRecords.size());
          d.epoch = epochIndex;
          if (p.vertexJob >= 0)  // the window vertices' address is known once work is
            d.vertices = {static_cast<std::uint32_t>(p.vertexJob), 0xFFFFFFFFu};
          drawRecords.push_back(d);
          triangles += record.count;
        } else if (record.kind == TileCommandKind::Read) {
          record.first = arenaWords;
          const std::uint32_t words =
              readWords(static_cast<TileReadForm>(record.count), p.rect.area());
          readCopies.push_back({p.destination, p.destinationOffset, arenaWords, words});
          arenaWords += words;
        }
        commandRecords.push_back(record);
      }
      e.commandEnd = static_cast<std::uint32_t>(commandRecords.size());
      jobs += e.gridWidth * e.gridHeight;
      epochRecords.push_back(e);
    }
    if (resolves) {
      TileResolveRange r;
      r.rect[0] = resolveRect.x0;
      r.rect[1] = resolveRect.y0;
      r.rect[2] = resolveRect.x1;
      r.rect[3] = resolveRect.y1;
      r.target = t;
      r.firstEpoch = firstEpoch;
      r.epochEnd = static_cast<std::uint32_t>(epochRecords.size());
      r.firstPixel = resolvePixels;
      resolvePixels += static_cast<std::uint32_t>(resolveRect.area());
      resolveRecords.push_back(r);
    }
  }
  std::vector<double> transforms;  // kTileTransformDoubles a vertex job
  for (const VertexJob& job : vertexJobs)
    transforms.insert(transforms.end(), job.source.transform.begin(), job.source.transform.end());
  std::vector<TileBoxJob> boxRecords;
  std::vector<double> poses;  // kTilePoseDoubles a box job, bound where the transforms are
  for (const BoxBatch& batch : boxBatches) {
    for (const BoxRequest& b : batch.blocks) {
      TileBoxJob job;
      job.local = TileAddress::of(b.local);
      job.vertexCount = b.vertexCount;
      job.pose = static_cast<std::uint32_t>(boxRecords.size());
      poses.insert(poses.end(), b.pose.begin(), b.pose.end());
      boxRecords.push_back(job);
    }
  }

  // The work buffer's regions.
  TileFrameConstants k;
  k.vertexCount = windowVertices;
  k.vertexJobs = static_cast<std::uint32_t>(vertexJobs.size());
  k.triangleCount = triangles;
  k.drawCount = static_cast<std::uint32_t>(drawRecords.size());
  k.jobCount = jobs;
  k.epochCount = static_cast<std::uint32_t>(epochRecords.size());
  k.pairCapacity = 4 * triangles + 2 * jobs + 4096;
  // Eight jobs a workgroup on a GPU; on a CPU driver, where each workgroup has a fixed cost of
  // several microseconds, enough that the frame is a few dozen workgroups.
  k.jobsPerGroup = context.cpuDriver() ? std::max(8u, (jobs / 32 + 7) / 8 * 8) : 8u;
  k.resolvePixels = resolvePixels;
  k.resolveRanges = static_cast<std::uint32_t>(resolveRecords.size());
  k.boxJobs = static_cast<std::uint32_t>(boxRecords.size());
  const VkDeviceSize triangleBytes =
      aligned(VkDeviceSize{triangles} * kTileWordsPerTriangle * 4 + 4);
  const VkDeviceSize jobBytes = aligned(VkDeviceSize{jobs} * 4 + 4);
  const VkDeviceSize countsAt = triangleBytes;
  const VkDeviceSize offsetsAt = countsAt + jobBytes;
  const VkDeviceSize cursorsAt = offsetsAt + jobBytes;
  const VkDeviceSize pairsAt = cursorsAt + jobBytes;
  const VkDeviceSize finalsAt = pairsAt + aligned(VkDeviceSize{k.pairCapacity} * 4);
  const VkDeviceSize windowsAt = finalsAt + aligned(VkDeviceSize{jobs} * 256 + 4);
  const VkDeviceSize arenaAt = windowsAt + aligned(VkDeviceSize{windowVertices} * 12 + 4);
  const VkDeviceSize boxesAt = arenaAt + aligned(VkDeviceSize{arenaWords} * 4 + 4);
  const VkDeviceSize workBytes = boxesAt + aligned(VkDeviceSize{k.boxJobs} * 64 + 8);
  reserveWork(workBytes);
  const VkBuffer w = work.buffer;
  const VkDeviceAddress workAddress = context.address(w);
  std::vector<TileVertexJob> vertexRecords;
  for (std::size_t j = 0; j < vertexJobs.size(); ++j) {
    TileVertexJob r;
    r.local = TileAddress::of(vertexJobs[j].source.local);
    r.windows = TileAddress::of(workAddress + windowsAt + VkDeviceSize{windowFirst[j]} * 12);
    r.firstVertex = windowFirst[j];
    r.vertexCount = vertexJobs[j].source.vertexCount;
    r.transform = static_cast<std::uint32_t>(j);
    vertexRecords.push_back(r);
  }
  for (TileDrawSource& d : drawRecords)
    if (d.vertices.high == 0xFFFFFFFFu)
      d.vertices = vertexRecords[d.vertices.low].windows;
  const TileBuffer targetsIn = uploaded(TileBinding::Targets, targetRecords);
  const TileBuffer epochsIn = uploaded(TileBinding::Epochs, epochRecords);
  const TileBuffer commandsIn = uploaded(TileBinding::Commands, commandRecords);
  const TileBuffer drawsIn = uploaded(TileBinding::Draws, drawRecords);
  const TileBuffer vertexJobsIn = uploaded(TileBinding::VertexJobs, vertexRecords);
  const TileBuffer transformsIn = uploaded(TileBinding::Transforms, transforms);
  const TileBuffer posesIn = uploaded(TileBinding::Transforms, poses);
  const TileBuffer resolveIn = uploaded(TileBinding::ResolveRanges, resolveRecords);
  const TileBuffer boxJobsIn = uploaded(TileBinding::BoxJobs, boxRecords);
  const TileBuffer triangleBuffer{TileBinding::Triangles, w, 0, triangleBytes};
  const TileBuffer counts{TileBinding::BinCounts, w, countsAt, jobBytes};
  const TileBuffer offsets{TileBinding::BinOffsets, w, offsetsAt, jobBytes};
  const TileBuffer cursors{TileBinding::BinCursors, w, cursorsAt, jobBytes};
  const TileBuffer pairs{TileBinding::Pairs, w, pairsAt, finalsAt - pairsAt};
  const TileBuffer finals{TileBinding::JobFinal, w, finalsAt, windowsAt - finalsAt};
  const TileBuffer arena{TileBinding::ReadArena, w, arenaAt, boxesAt - arenaAt};
  const TileBuffer boxesOut{TileBinding::Boxes, w, boxesAt, workBytes - boxesAt};

  timed = queries != VK_NULL_HANDLE;
  if (timed)
    vkCmdResetQueryPool(cmd, queries, 0, kTimestamps);
  long long dispatches = 0;
  const auto dispatchLinear = [&](VkPipeline p, std::initializer_list<TileBuffer> buffers,
                                  std::uint64_t count) {
    if (count == 0)
      return;
    pipelines.dispatchLinear(cmd, p, buffers, k, count);
    ++dispatches;
  };
  const auto dispatchGroups = [&](VkPipeline p, std::initializer_list<TileBuffer> buffers,
                                  std::uint64_t groups) {
    if (groups == 0)
      return;
    const auto perRow = static_cast<std::uint32_t>(std::min<std::uint64_t>(groups, 65535));
    pipelines.dispatch(cmd, p, buffers, k, perRow,
                       static_cast<std::uint32_t>((groups + perRow - 1) / perRow));
    ++dispatches;
  };
  // What the devices recorded before (uploads, framebuffer fills) is visible to the stages.
  computeBarrier(cmd);
  vkCmdFillBuffer(cmd, w, countsAt, jobBytes, 0);
  vkCmdFillBuffer(cmd, w, arenaAt, boxesAt - arenaAt, 0);  // stencil reads are ORed in
  computeBarrier(cmd);
  timestamp(cmd, 0);
  dispatchGroups(pipelines.box, {boxJobsIn, posesIn, boxesOut}, k.boxJobs);
  dispatchLinear(pipelines.vertex,
                 {targetsIn, epochsIn, commandsIn, drawsIn, vertexJobsIn, transformsIn},
                 windowVertices);
  computeBarrier(cmd);
  timestamp(cmd, 1);
  dispatchLinear(pipelines.setup,
                 {targetsIn, epochsIn, commandsIn, drawsIn, triangleBuffer, counts}, triangles);
  computeBarrier(cmd);
  timestamp(cmd, 2);
  if (triangles > 0) {
    pipelines.dispatch(cmd, context.cpuDriver() ? pipelines.scanSerial : pipelines.scan,
                       {counts, offsets, cursors}, k, 1, 1);
    ++dispatches;
    computeBarrier(cmd);
    dispatchLinear(pipelines.scatter,
                   {targetsIn, epochsIn, commandsIn, drawsIn, triangleBuffer, cursors, pairs},
                   triangles);
    computeBarrier(cmd);
    dispatchLinear(pipelines.sort, {counts, offsets, pairs}, jobs);
    computeBarrier(cmd);
  }
  timestamp(cmd, 3);
  dispatchGroups(pipelines.raster,
                 {targetsIn, epochsIn, commandsIn, drawsIn, triangleBuffer, counts, offsets, pairs,
                  finals, arena},
                 (jobs + k.jobsPerGroup - 1) / k.jobsPerGroup);
  computeBarrier(cmd);
  timestamp(cmd, 4);
  dispatchLinear(pipelines.resolve, {targetsIn, epochsIn, commandsIn, drawsIn, finals, resolveIn},
                 resolvePixels);
  // The reads and boxes to their destinations (the summaries' dispatch comes after, with its own
  // barrier), grouped by destination buffer.
  std::map<VkBuffer, std::vector<VkBufferCopy>> copies;
  for (const ReadCopy& r : readCopies)
    if (r.words > 0)
      copies[r.destination].push_back(
          {arenaAt + VkDeviceSize{r.firstWord} * 4, r.offset, VkDeviceSize{r.words} * 4});
  std::uint32_t box = 0;
  for (const BoxBatch& batch : boxBatches) {
    if (!batch.blocks.empty())
      copies[batch.destination].push_back(
          {boxesAt + VkDeviceSize{box} * 64, batch.offset, batch.blocks.size() * 64});
    box += static_cast<std::uint32_t>(batch.blocks.size());
  }
  for (const auto& [destination, regions] : copies)
    vkCmdCopyBuffer(cmd, w, destination, static_cast<std::uint32_t>(regions.size()),
                    regions.data());
  if (captured) {
    const auto [drawIndex, epochIndex] = *captured;
    const TileDrawSource d = drawRecords[drawIndex];
    const TileEpoch e = epochRecords[epochIndex];
    std::optional<std::pair<VkDeviceSize, std::uint32_t>> windows;  // offset, vertices
    const Pending& p = commands[capture->target][capture->command];
    if (p.vertexJob >= 0)
      windows = std::make_pair(
          windowsAt + VkDeviceSize{windowFirst[static_cast<std::size_t>(p.vertexJob)]} * 12,
          vertexJobs[static_cast<std::size_t>(p.vertexJob)].source.vertexCount);
    const VkDeviceSize bytes = finalsAt;  // triangles, bins and lists
    const VkDeviceSize windowBytes = windows ? VkDeviceSize{windows->second} * 12 : 0;
    const CommandRecorder::Staged out = recorder.results(
        bytes + windowBytes,
        [d, e, bytes, pairsAt, countsAt, offsetsAt, windowBytes, capacity = k.pairCapacity,
         sink = std::move(capture->sink)](const std::uint8_t* data) {
          const auto word = [&](VkDeviceSize at) {
            std::uint32_t v = 0;
            std::memcpy(&v, data + at, 4);
            return v;
          };
          TileDrawCapture c;
          c.firstTriangle = d.firstTriangle;
          for (std::uint32_t i = 0; i < d.triangleCount * kTileWordsPerTriangle; ++i)
            c.triangleWords.push_back(
                word((VkDeviceSize{d.firstTriangle} * kTileWordsPerTriangle + i) * 4));
          c.gridOrigin[0] = e.gridOrigin[0];
          c.gridOrigin[1] = e.gridOrigin[1];
          c.gridWidth = e.gridWidth;
          c.gridHeight = e.gridHeight;
          for (std::uint32_t b = 0; b < e.gridWidth * e.gridHeight; ++b) {
            const std::uint32_t job = e.firstJob + b;
            const std::uint32_t n = word(countsAt + VkDeviceSize{job} * 4);
            const std::uint32_t at = word(offsetsAt + VkDeviceSize{job} * 4);
            const bool overflowed = at + n > capacity;
            std::vector<std::uint32_t> list;
            for (std::uint32_t i = 0; i < n && !overflowed; ++i)
              list.push_back(word(pairsAt + (VkDeviceSize{at} + i) * 4));
            c.overflowed.push_back(overflowed);
            c.jobLists.push_back(std::move(list));
          }
          c.windowVertices.resize(windowBytes / 4);
          std::memcpy(c.windowVertices.data(), data + bytes, windowBytes);
          sink(std::move(c));
        });
    const VkBufferCopy back{0, out.offset, bytes};
    vkCmdCopyBuffer(cmd, w, out.buffer, 1, &back);
    if (windows) {
      const VkBufferCopy windowCopy{windows->first, out.offset + bytes, windowBytes};
      vkCmdCopyBuffer(cmd, w, out.buffer, 1, &windowCopy);
    }
  }
  computeBarrier(cmd);
  timestamp(cmd, 5);
  raster::TransferCounters counted;
  counted.dispatches = dispatches;
  recorder.count(counted);

  for (std::vector<Pending>& list : commands)
    list.clear();
  vertexJobs.clear();
  vertexJobOfKey.clear();
  boxBatches.clear();
  capture.reset();
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
      0, [impl](VkCommandBuffer cmd) { impl->run(cmd); }, [impl] { impl->readTimes(); });
}

TileFrame::~TileFrame() = default;

std::uint32_t TileFrame::addTarget(VkBuffer framebuffer, int width, int height) {
  Impl& f = *impl_;
  Impl::Target target{true, f.context.address(framebuffer), static_cast<std::uint32_t>(width),
                      static_cast<std::uint32_t>(height)};
  for (std::uint32_t t = 0; t < f.targets.size(); ++t) {
    if (!f.targets[t].live && f.commands[t].empty()) {
      f.targets[t] = target;
      return t;
    }
  }
  f.targets.push_back(target);
  f.commands.emplace_back();
  return static_cast<std::uint32_t>(f.targets.size() - 1);
}

void TileFrame::removeTarget(std::uint32_t target) {
  impl_->targets.at(target).live = false;
  impl_->commands.at(target).clear();
}

void TileFrame::clearDepth(std::uint32_t target, const PixelRect& scissor, std::uint32_t q) {
  impl_->add(target, TileCommandKind::ClearDepth, scissor).command.value = q;
}

void TileFrame::clearStencil(std::uint32_t target, const PixelRect& scissor, std::uint8_t value,
                             std::uint8_t writeMask) {
  Impl::Pending& p = impl_->add(target, TileCommandKind::ClearStencil, scissor);
  p.command.value = value;
  p.command.stencil = std::uint32_t{writeMask} << 16;
}

void TileFrame::draw(std::uint32_t target, const raster::RenderState& state,
                     const TileVertices& vertices, VkDeviceAddress indices,
                     std::uint32_t triangles) {
  Impl& f = *impl_;
  Impl::Pending& p = f.add(target, TileCommandKind::Draw, state.scissor);
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
  p.vertexJob = static_cast<int>(f.vertexJobs.size());
  f.vertexJobs.push_back({vertices});
  if (vertices.contentKey != 0)
    f.vertexJobOfKey[vertices.contentKey] = p.vertexJob;
}

void TileFrame::read(std::uint32_t target, const PixelRect& rect, TileReadForm form,
                     VkBuffer destination, VkDeviceSize offset) {
  Impl::Pending& p = impl_->add(target, TileCommandKind::Read, rect);
  p.command.count = static_cast<std::uint32_t>(form);
  p.destination = destination;
  p.destinationOffset = offset;
}

void TileFrame::boxes(const std::vector<BoxRequest>& blocks, VkBuffer destination,
                      VkDeviceSize offset) {
  impl_->recorder.open();
  impl_->boxBatches.push_back({blocks, destination, offset});
}

void TileFrame::captureLastDraw(std::uint32_t target, std::function<void(TileDrawCapture)> sink) {
  Impl& f = *impl_;
  const std::vector<Impl::Pending>& list = f.commands.at(target);
  for (std::size_t c = list.size(); c > 0; --c) {
    if (list[c - 1].command.kind == TileCommandKind::Draw) {
      f.capture = Impl::Capture{target, c - 1, std::move(sink)};
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
