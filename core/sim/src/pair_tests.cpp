// Running a frame's pair tests, sequentially or on oneTBB's threads, into slots in task order.
#include "pair_tests.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "recode/refine/adaptive.hpp"

#include "device_pool.hpp"

namespace recode::core {

namespace {

// The pair test of `mode`. The adaptive mode's tester (and its refinement device) is one per
// thread, as each lane runs its tests in turn on one thread.
PairResult testPair(raster::DepthStencilDevice& device, const PairTask& task, PairMode mode) {
  switch (mode) {
    case PairMode::Reference:
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

void runOne(raster::DepthStencilDevice& device, const PairTask& task, PairOutcome& outcome,
            PairMode mode) {
  try {
    outcome.result = testPair(device, task, mode);
    // The report keeps no case map; dropping it here bounds the memory the slots hold.
    outcome.result.caseMap = {};
    // Swapped with an empty vector: `points = {}` would keep the capacity (9 MB for a pair of
    // 374,004 interfering pixels).
    if (!task.keepContactPoints)
      std::vector<Eigen::Vector3d>().swap(outcome.result.contact.points);
  } catch (...) {
    outcome.error = std::current_exception();
  }
}

std::pair<int, int> sizeOf(const PairTask& task) {
  return {task.request.frame.width, task.request.frame.height};
}

// The tests of one device, in task order.
struct Lane {
  raster::DepthStencilDevice* device = nullptr;
  std::vector<std::size_t> tasks;
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
    : concurrency_(pairTestThreads(options)), mode_(options.pairMode) {
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
  if (!impl_->arena) {
    for (std::size_t i = 0; i < count; ++i) {
      const auto [width, height] = sizeOf(tasks[i]);
      runOne(pool.at(width, height, 0), tasks[i], outcomes[i], mode_);
      if (outcomes[i].error)
        break;
    }
    return outcomes;
  }
  // Deal each size's tests in turn to its devices' lanes.
  std::vector<Lane> lanes;
  std::map<std::pair<int, int>, std::pair<std::size_t, int>> dealt;  // first lane, tests dealt
  for (std::size_t i = 0; i < count; ++i) {
    const std::pair<int, int> size = sizeOf(tasks[i]);
    auto [entry, added] = dealt.try_emplace(size, lanes.size(), 0);
    const int devices = lanes_.at(size);
    if (added)
      for (int d = 0; d < devices; ++d)
        lanes.push_back({&pool.at(size.first, size.second, d), {}});
    auto& [first, n] = entry->second;
    lanes[first + static_cast<std::size_t>(n++ % devices)].tasks.push_back(i);
  }
  impl_->arena->execute([&] {
    tbb::parallel_for(std::size_t{0}, lanes.size(), [&](std::size_t l) {
      for (std::size_t i : lanes[l].tasks) {
        runOne(*lanes[l].device, tasks[i], outcomes[i], mode_);
        if (outcomes[i].error)
          break;
      }
    });
  });
  return outcomes;
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
