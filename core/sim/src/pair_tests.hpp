#pragma once
// The pair tests of one frame: the leaf pairs the descent found, each given to collidePair on a
// device of its frame's size (or, on devices that defer their commands, all given to
// collidePairs as one batch). With more than one thread they run in parallel (oneTBB, in an
// arena of the run's size), each into its own slot of the answer, so that whatever order they
// finish in, the caller reads them in the order they were listed and the frame's report is the
// same bytes as a sequential run's.

#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "recode/pair/pair.hpp"
#include "recode/sim/hierarchy.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::core {

struct PairTask {
  int objectA = 0, objectB = 0;
  LeafPair leaves;
  const PairBlock* blockA = nullptr;  // world blocks, alive while the tests run
  const PairBlock* blockB = nullptr;
  PairRequest request;
  bool keepContactPoints = true;  // RunOptions::keepContactPoints
};

// A task's answer: its result (the case map cleared), or what it threw.
struct PairOutcome {
  PairResult result;
  std::exception_ptr error;
};

class PairTestRunner {
 public:
  // Runs on pairTestThreads(options) threads, with options.deviceFactory's devices.
  explicit PairTestRunner(const RunOptions& options);
  ~PairTestRunner();
  PairTestRunner(const PairTestRunner&) = delete;
  PairTestRunner& operator=(const PairTestRunner&) = delete;

  // How many pair tests may run at once: 1 on the sequential path.
  [[nodiscard]] int concurrency() const { return concurrency_; }

  // Makes the devices the tasks need, in task order. Each frame size has one device, and
  // with threads one more (up to one per test of that size this frame, and concurrency())
  // once its devices have run kTestsPerExtraDevice tests each: a big frame seen in a few
  // frames (a rotating pair's) costs one device, as sequentially, as making it costs more than
  // the tests it would share, while a size that recurs grows to concurrency() devices. `usable`
  // tasks got theirs: all, unless making the device of task `usable` threw `error` (the tasks
  // before it can still run, as they would have run before it sequentially). A frame batched on
  // deferring devices gets one device per test of a size instead, within
  // RunOptions::batchDevicesPerSize and kMaxBatchPixelsPerSize.
  struct DeviceSetup {
    double us = 0.0;  // spent making devices
    std::size_t usable = 0;
    std::exception_ptr error;
  };
  [[nodiscard]] DeviceSetup reserveDevices(const std::vector<PairTask>& tasks);

  // Runs tasks [0, count): outcome i is task i's. Sequentially it stops at the first error, as
  // the tasks after it would not have run. In parallel each of a size's devices is a lane that
  // takes that size's next test, in task order, whenever it is free; after an error the size's
  // lanes take no more, and the caller takes the first error in task order (a test left
  // unrun comes after an error).
  [[nodiscard]] std::vector<PairOutcome> run(const std::vector<PairTask>& tasks, std::size_t count);

  // Runs body(i) for i in [0, n) on the runner's threads (in order on the sequential path),
  // then rethrows what the lowest i threw, if any: the error a sequential loop would meet first.
  void forEach(std::size_t n, const std::function<void(std::size_t)>& body);

  static constexpr long long kTestsPerExtraDevice = 32;

  // One of the runner's devices held now, or null before any was made: what kind of device the
  // factory makes.
  [[nodiscard]] const raster::DepthStencilDevice* anyDevice() const;

  // What the runner's devices held now have handed to hardware and back since they were made.
  [[nodiscard]] raster::TransferCounters transfers() const;

 private:
  // On the sequential path, with devices that defer their commands and a mode whose test is
  // collidePair: the frame's tests as one collidePairs batch, a size's tests going round its
  // devices (so consecutive tests of a size draw on devices of their own). Returns
  // false, leaving the outcomes empty, when the devices do not defer or a batch threw.
  bool runBatches(const std::vector<PairTask>& tasks, std::size_t count,
                  std::vector<PairOutcome>& outcomes);

  class Impl;
  std::unique_ptr<Impl> impl_;
  int concurrency_ = 1;
  PairMode mode_ = PairMode::Reference;
  bool batch_ = true;                                         // RunOptions::batch
  ContactSchedule schedule_ = ContactSchedule::AfterVerdict;  // RunOptions::contactSchedule
  int batchDevicesPerSize_ = 1;                               // RunOptions::batchDevicesPerSize
  std::map<std::pair<int, int>, int> lanes_;                  // devices per frame size this frame
};

}  // namespace recode::core
