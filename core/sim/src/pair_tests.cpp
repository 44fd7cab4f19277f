// Running a frame's pair tests, sequentially or on oneTBB's threads, into slots in task order.
#include "pair_tests.hpp"

#include <algorithm>
#include <atomic>
#include <map>
#include <optional>
#include <utility>

#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "recode/pair/pair_batch.hpp"
#include "recode/refine/adaptive.hpp"

#include "device_pool.hpp"

namespace recode::core {

namespace {

// The pair test of `mode`. The adaptive mode's tester (and its refinement device) is one per
// thread, as each lane runs its tests in turn on one thread.
PairResult testPair(raster::DepthStencilDevice& device, const PairTask& task, PairMode mode) {
  switch (mode) {
    case PairMode::Reference:
    case PairMode::SkipApart:  // the simulation has left out the pairs proven apart
      break;
    case PairMode::Conservative:
      return collideConservative(device, task.blockA->mesh(), task.blockB->mesh(), task.request)
          .pair;
    case PairMode::Adaptive: {
      thread_local AdaptivePairTester tester;
      AdaptiveResult r = tester.collide(device, *task.blockA, *task.blockB, task.request);
      PairResult out = r.contact     ? std::move(*r.contact)
                       : r.reference ? std::move(*r.reference)
                                     : PairResult{};
      out.collide = r.verdict == PairVerdict::Collide;
      return out;
    }
  }
  return collidePair(device, *task.blockA, *task.blockB, task.request);
}

// What the report keeps of a result.
void keepForReport(const PairTask& task, PairResult& result) {
  // The report keeps no case map; dropping it here bounds the memory the slots hold.
  result.caseMap = {};
  // Swapped with an empty vector: `points = {}` would keep the capacity (9 MB for a pair of
  // 374,004 interfering pixels).
  if (!task.keepContactPoints)
    std::vector<Eigen::Vector3d>().swap(result.contact.points);
}

void runOne(raster::DepthStencilDevice& device, const PairTask& task, PairOutcome& outcome,
            PairMode mode) {
  try {
    outcome.result = testPair(device, task, mode);
    keepForReport(task, outcome.result);
  } catch (...) {
    outcome.error = std::current_exception();
  }
}

// The modes whose pair test is collidePair itself, so a batch of them is collidePairs.
bool batches(PairMode mode) {
  return mode == PairMode::Reference || mode == PairMode::SkipApart;
}

std::pair<int, int> sizeOf(const PairTask& task) {
  return {task.request.frame.width, task.request.frame.height};
}

// The tests of one frame size, in task order, taken one at a time by that size's lanes. After
// an error no lane takes another, so every test not run comes after it in task order.
struct SizeQueue {
  std::vector<std::size_t> tasks;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stopped{false};
};

// One device and the queue it takes its tests from.
struct Lane {
  raster::DepthStencilDevice* device = nullptr;
  SizeQueue* queue = nullptr;
};

}  // namespace

int pairTestThreads(const RunOptions& options) {
  if (options.deviceFactory || options.threads == 1)
    return 1;
  // More than the machine's threads would not run at once (oneTBB warns and ignores them).
  const int hardware = tbb::info::default_concurrency();
  return options.threads > 0 ? std::min(options.threads, hardware) : hardware;
}

class PairTestRunner::Impl {
 public:
  Impl(DeviceFactory factory, int concurrency) : pool(std::move(factory)) {
    if (concurrency > 1)
      arena.emplace(concurrency);
  }

  DevicePool pool;
  std::optional<tbb::task_arena> arena;  // none on the sequential path
};

PairTestRunner::PairTestRunner(const RunOptions& options)
    : concurrency_(pairTestThreads(options)),
      mode_(options.pairMode),
      batch_(options.batch),
      schedule_(options.contactSchedule),
      batchDevicesPerSize_(options.batchDevicesPerSize) {
  impl_ = std::make_unique<Impl>(options.deviceFactory, concurrency_);
}

PairTestRunner::~PairTestRunner() = default;

PairTestRunner::DeviceSetup PairTestRunner::reserveDevices(const std::vector<PairTask>& tasks) {
  std::map<std::pair<int, int>, int> tests;
  for (const PairTask& task : tasks)
    ++tests[sizeOf(task)];
  std::vector<std::pair<int, int>> sizes;
  for (const auto& entry : tests)
    sizes.push_back(entry.first);
  DevicePool& pool = impl_->pool;
  pool.trim(sizes);

  lanes_.clear();
  DeviceSetup setup;
  for (; setup.usable < tasks.size(); ++setup.usable) {
    const auto [width, height] = sizeOf(tasks[setup.usable]);
    auto [lanes, added] = lanes_.try_emplace({width, height}, 0);
    if (!added)
      continue;
    const int held = pool.held(width, height);
    const bool earned = pool.uses(width, height) >= kTestsPerExtraDevice * held;
    lanes->second =
        std::min({tests[{width, height}], concurrency_, std::max(held + (earned ? 1 : 0), 1)});
    try {
      setup.us += pool.reserve(width, height, lanes->second);
      // A batch of pairs on devices of their own records them wave by wave (collidePairs), one
      // barrier a wave rather than one a pair: a deferring device of this size for each of its
      // tests, up to batchDevicesPerSize_ and kMaxBatchPixelsPerSize pixels in all.
      if (batchDevicesPerSize_ > 1 && concurrency_ == 1 && batch_ && batches(mode_) &&
          pool.at(width, height, 0).defers()) {
        const long long byPixels =
            std::max(1LL, kMaxBatchPixelsPerSize / (static_cast<long long>(width) * height));
        lanes->second =
            static_cast<int>(std::min({static_cast<long long>(tests[{width, height}]),
                                       static_cast<long long>(batchDevicesPerSize_), byPixels}));
        setup.us += pool.reserve(width, height, lanes->second);
      }
    } catch (...) {
      setup.error = std::current_exception();
      break;
    }
  }
  for (const auto& [size, n] : tests)  // counted after this frame's devices were chosen
    pool.addUses(size.first, size.second, n);
  return setup;
}

std::vector<PairOutcome> PairTestRunner::run(const std::vector<PairTask>& tasks,
                                             std::size_t count) {
  std::vector<PairOutcome> outcomes(count);
  DevicePool& pool = impl_->pool;
  if (!impl_->arena && batch_ && batches(mode_) && runBatches(tasks, count, outcomes))
    return outcomes;
  if (!impl_->arena) {
    for (std::size_t i = 0; i < count; ++i) {
      const auto [width, height] = sizeOf(tasks[i]);
      runOne(pool.at(width, height, 0), tasks[i], outcomes[i], mode_);
      if (outcomes[i].error)
        break;
    }
    return outcomes;
  }
  // Each size's tests form a queue that its devices' lanes take from, in task order, as each
  // finishes its last: the tests of a frame differ in cost by orders of magnitude, and a lane
  // never waits while a test it could run is left. Which device runs a test changes no result.
  std::map<std::pair<int, int>, SizeQueue> queues;
  for (std::size_t i = 0; i < count; ++i)
    queues[sizeOf(tasks[i])].tasks.push_back(i);
  std::vector<Lane> lanes;
  for (auto& [size, queue] : queues)
    for (int d = 0; d < lanes_.at(size); ++d)
      lanes.push_back({&pool.at(size.first, size.second, d), &queue});
  impl_->arena->execute([&] {
    tbb::parallel_for(std::size_t{0}, lanes.size(), [&](std::size_t l) {
      SizeQueue& queue = *lanes[l].queue;
      while (!queue.stopped.load()) {
        const std::size_t k = queue.next.fetch_add(1);
        if (k >= queue.tasks.size())
          break;
        const std::size_t i = queue.tasks[k];
        runOne(*lanes[l].device, tasks[i], outcomes[i], mode_);
        if (outcomes[i].error)
          queue.stopped.store(true);
      }
    });
  });
  return outcomes;
}

const raster::DepthStencilDevice* PairTestRunner::anyDevice() const {
  return impl_->pool.anyHeld();
}

raster::TransferCounters PairTestRunner::transfers() const {
  return impl_->pool.transfers();
}

bool PairTestRunner::runBatches(const std::vector<PairTask>& tasks, std::size_t count,
                                std::vector<PairOutcome>& outcomes) {
  DevicePool& pool = impl_->pool;
  std::vector<raster::DepthStencilDevice*> devices;
  std::vector<PairJob> jobs;
  devices.reserve(count);
  jobs.reserve(count);
  std::map<std::pair<int, int>, int> next;  // each size's tests go round its devices
  for (std::size_t i = 0; i < count; ++i) {
    const auto [width, height] = sizeOf(tasks[i]);
    int& k = next[{width, height}];
    devices.push_back(&pool.at(width, height, k));
    k = (k + 1) % lanes_.at({width, height});
    if (!devices.back()->defers())
      return false;  // one device runs the tests one by one anyway
    jobs.push_back({tasks[i].blockA, tasks[i].blockB, tasks[i].request});
  }
  try {
    std::vector<PairResult> results = collidePairs(devices, jobs, schedule_);
    for (std::size_t i = 0; i < count; ++i) {
      outcomes[i].result = std::move(results[i]);
      keepForReport(tasks[i], outcomes[i].result);
    }
  } catch (...) {
    // Which test threw, and which ran before it, is the sequential path's to say: the frame is
    // run again test by test (an error is rare; its report must be the sequential one).
    std::fill(outcomes.begin(), outcomes.end(), PairOutcome{});
    return false;
  }
  return true;
}

void PairTestRunner::forEach(std::size_t n, const std::function<void(std::size_t)>& body) {
  if (!impl_->arena) {
    for (std::size_t i = 0; i < n; ++i)
      body(i);
    return;
  }
  std::vector<std::exception_ptr> errors(n);
  impl_->arena->execute([&] {
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
      try {
        body(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  });
  for (const std::exception_ptr& error : errors)
    if (error)
      std::rethrow_exception(error);
}

}  // namespace recode::core
