// Running a frame's pair tests, sequentially or on oneTBB's threads, into slots in task order.
#include "pair_tests.hpp"

#include <map>
#include <optional>
#include <utility>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "device_pool.hpp"

namespace recode::core {

namespace {

// Borrows a device for one test and gives it back however the test ends.
class BorrowedDevice {
 public:
  BorrowedDevice(DevicePool& pool, const FrameSpec& frame)
      : pool_(pool), device_(pool.borrow(frame.width, frame.height)) {}
  ~BorrowedDevice() { pool_.release(device_); }
  BorrowedDevice(const BorrowedDevice&) = delete;
  BorrowedDevice& operator=(const BorrowedDevice&) = delete;
  raster::DepthStencilDevice& get() { return device_; }

 private:
  DevicePool& pool_;
  raster::DepthStencilDevice& device_;
};

void runOne(DevicePool& pool, const PairTask& task, PairOutcome& outcome) {
  try {
    BorrowedDevice device(pool, task.request.frame);
    outcome.result = collidePair(device.get(), *task.meshA, *task.meshB, task.request);
    // The report keeps no case map; dropping it here bounds the memory the slots hold.
    outcome.result.caseMap = {};
  } catch (...) {
    outcome.error = std::current_exception();
  }
}

}  // namespace

int pairTestThreads(const RunOptions& options) {
  if (options.deviceFactory || options.threads == 1)
    return 1;
  return options.threads > 0 ? options.threads : tbb::info::default_concurrency();
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

PairTestRunner::PairTestRunner(const RunOptions& options) : concurrency_(pairTestThreads(options)) {
  impl_ = std::make_unique<Impl>(options.deviceFactory, concurrency_);
}

PairTestRunner::~PairTestRunner() = default;

PairTestRunner::DeviceSetup PairTestRunner::reserveDevices(const std::vector<PairTask>& tasks) {
  std::map<std::pair<int, int>, int> wanted;  // tests per frame size
  for (const PairTask& task : tasks)
    ++wanted[{task.request.frame.width, task.request.frame.height}];
  std::vector<std::pair<int, int>> sizes;
  for (const auto& [size, count] : wanted)
    sizes.push_back(size);
  impl_->pool.trim(sizes);

  DeviceSetup setup;
  for (; setup.usable < tasks.size(); ++setup.usable) {
    const FrameSpec& frame = tasks[setup.usable].request.frame;
    const int count = std::min(wanted[{frame.width, frame.height}], concurrency_);
    try {
      setup.us += impl_->pool.reserve(frame.width, frame.height, count);
    } catch (...) {
      setup.error = std::current_exception();
      break;
    }
  }
  return setup;
}

std::vector<PairOutcome> PairTestRunner::run(const std::vector<PairTask>& tasks,
                                             std::size_t count) {
  std::vector<PairOutcome> outcomes(count);
  if (!impl_->arena) {
    for (std::size_t i = 0; i < count; ++i) {
      runOne(impl_->pool, tasks[i], outcomes[i]);
      if (outcomes[i].error)
        break;
    }
    return outcomes;
  }
  impl_->arena->execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i)
                          runOne(impl_->pool, tasks[i], outcomes[i]);
                      });
  });
  return outcomes;
}

}  // namespace recode::core
