#pragma once
// Running a scene over frames (`recode run`): per frame, pose every object, update its boxes,
// find candidate object pairs by sort and sweep, descend each pair's trees to the leaf pairs
// whose boxes overlap, and run the pair algorithm on each, in its own frame.
//
// The frame of a leaf pair: the view axis of the scene, a window over the two leaves' world
// AABBs (grown by kDefaultWindowMargin) and square pixels of the run's pixel size, the
// window's sides rounded up to a multiple of kPairFrameGranule pixels so that a few device
// sizes serve all pairs. The run's pixel size is the scene's (or the command line's)
// "pixel_size"; else the pixel a W x H screen (the scene's resolution, else 800 x 800) would
// have over the scene's window (given, else the default window over all objects at frame 0).
// It is one pixel size for the whole run, so accuracy does not depend on which pair is drawn.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_batch.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/posed_boxes.hpp"
#include "recode/refine/pair_mode.hpp"
#include "recode/refine/view_axis_choice.hpp"
#include "recode/scene/scene.hpp"
#include "recode/sim/broad_phase.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode::core {

class PairTestRunner;   // core/sim/src/pair_tests.hpp
class FrameLeafBlocks;  // core/sim/src/frame_leaf_blocks.hpp
struct PairTask;        // core/sim/src/pair_tests.hpp

inline constexpr int kPairFrameGranule = 32;
inline constexpr int kDefaultRunFrames = 100;  // when neither the scene nor the caller says
// The most pair tests (leaf pairs whose boxes overlap) one frame may list by default: a frame
// holds its tests and their results at once, so this bounds a run's memory (a few hundred
// bytes per test without contact points). 3,000 coincident cones list 4,498,500.
inline constexpr long long kDefaultMaxPairTestsPerFrame = 100'000;
inline constexpr long long kMaxPairTestsPerFrameLimit = 10'000'000;  // the most it may be raised to

// Makes a device with a framebuffer of width x height pixels. The simulation keeps the
// devices it made, per frame size one (more with threads, for sizes that recur), and uses
// them frame after frame.
using DeviceFactory =
    std::function<std::unique_ptr<raster::DepthStencilDevice>(int width, int height)>;

struct RunOptions {
  FrameOverrides overrides;  // --resolution (of the scene's screen) or --pixel-size
  MorMode mor = MorMode::Min;
  bool contact = true;  // measure contact regions (the two extra depth passes)
  // Where the pairs are drawn; empty: raster::CpuDevice, the reference. A GL device here runs
  // the same command stream on a real GL implementation (`recode bench`'s recode-gl column).
  DeviceFactory deviceFactory;
  // Draw every pair in the scene's whole screen (resolveFrame of the scene's view over the
  // objects at frame 0: the frame `recode pair` would use) instead of a frame around the
  // pair's two blocks. The paper drew into the screen; its FULL MOR read all of it, and
  // `recode bench`'s Table 1 reproduces that with this option. MIN and MAX cover the same
  // pixels either way (the pixel size is the same); blocks outside the screen are clipped.
  bool drawOnScreen = false;
  // Threads the pair tests of a frame may run on (oneTBB): 0 all hardware threads, 1 none but
  // the caller's, N at most N. Only with the default (CPU) device: a deviceFactory may make
  // GPU-API devices, which share one context and are not to be used from several threads, so
  // with one the pair tests always run sequentially. The report is the same bytes whatever
  // the count (the tests run into slots read in the sequential order); only times differ.
  int threads = 0;
  // A frame that would list more pair tests stops the run with an error naming the frame, the
  // count so far and the limit (docs/scenes.md, "Limits of a run"); at least 1.
  long long maxPairTestsPerFrame = kDefaultMaxPairTestsPerFrame;
  // Keep each contact's points (one per interfering pixel) in the frame report. `recode run`
  // prints only counts, area and box, and turns this off so that a frame's memory does not
  // grow with its contact areas.
  bool keepContactPoints = true;
  // How each leaf pair is decided (docs/algorithm.md, "Beyond the paper"): the reference
  // algorithm in the pair's frame, adaptive refinement (a contact is one the refinement saw;
  // the result is the run that saw it) or the conservative mode (the result is that of the
  // grown blocks), or the skip-apart mode (the reference, except that a pair proven apart in its
  // frame is not drawn: the same contacts, fewer pixels read). Reports of the reference mode
  // are unchanged.
  PairMode pairMode = PairMode::Reference;
  // The axis each leaf pair is drawn along (docs/algorithm.md, "Beyond the paper"): the
  // scene's (the default: reports unchanged), or the one a rule chooses for the pair from its
  // leaves' world AABBs and OBBs, at the run's pixel size. Composes with every pairMode; not
  // with drawOnScreen, whose screen has the scene's axis.
  ViewAxisRule viewAxisRule = ViewAxisRule::Scene;
  // Give a frame's pair tests to a device that defers its commands (the Vulkan device) as one
  // collidePairs batch per frame size: one submission a frame instead of three a pair test.
  // Off, each test is collidePair on its own (`recode run --per-pair`, the bench's
  // per-pair column). The reports are the same bytes either way; the reference and skip-apart
  // modes batch, the conservative and adaptive modes run pair by pair.
  bool batch = true;
  // When a batch draws its contact passes (pair_batch.hpp): after the stencil's verdict (two
  // submissions a frame), or speculatively with the stencil passes (one). The same reports.
  ContactSchedule contactSchedule = ContactSchedule::AfterVerdict;
  // With a batch on deferring devices: how many devices each frame size may have, so that a
  // frame's tests of one size go round them and collidePairs records them in waves of pairs on
  // devices of their own (one barrier a wave's half-segment on Vulkan, not one a pair), within
  // kMaxBatchPixelsPerSize pixels a size. 1: one device a size. The same reports either way.
  int batchDevicesPerSize = 1;
  // With a batch on deferring devices and keepContactPoints off: conclude each pair test from
  // the device's 64-byte summaries of its buffers (PairRequest::keepPixels off; the Vulkan and
  // exact GL devices make them in a compute shader) instead of reading the stencil and depths
  // back. The same reports. Off by default: on lavapipe and llvmpipe it is slower
  // (docs/benchmarks.md, "GPU devices on lavapipe").
  bool deviceSummaries = false;
  // When the factory's devices keep blocks for posed draws and reduce boxes
  // (raster::PosedBoxReducer, vulkan-compute): from the frame after the first pair test, the
  // stale leaves' world boxes are reduced on such a device (one submission more a frame), so the
  // host maps no vertex; off, the host makes them (ObjectTree::updateAabbs). The same bits, so
  // the same reports.
  bool leafBoxesOnDevice = true;
};

inline constexpr int kMaxBatchDevicesPerSize = 64;  // the most batchDevicesPerSize may be
inline constexpr long long kMaxBatchPixelsPerSize = 16LL << 20;  // a size's devices' pixels at most

// A leaf pair whose blocks interfere at this frame.
struct LeafContact {
  int objectA = 0, objectB = 0;     // indices into Simulation::objects(), objectA < objectB
  int leafA = 0, leafB = 0;         // node indices in those trees
  PairResult result;                // caseMap cleared to keep reports small
  ViewAxis viewAxis = ViewAxis::Z;  // the axis the pair was drawn along
};

struct FrameReport {
  int frame = 0;
  std::vector<LeafContact> contacts;  // sorted by (objectA, objectB, leafA, leafB)
  long long objectPairs = 0;          // object pairs whose root AABBs overlap (broad phase)
  long long boxTests = 0;             // node pairs whose boxes were tested in the descent
  long long pairTests = 0;            // leaf pairs given to the pair algorithm
  long long pairTestsSkipped = 0;     // of those, pairs the skip-apart mode proved apart undrawn
  long long stencilPixelsRead = 0;
  long long depthPixelsRead = 0;
  // Wall-clock times: with several threads collisionUs is the elapsed time of the parallel
  // pair tests, not the sum of the threads' times.
  double frameUs = 0.0;      // the whole frame: posing the nodes + collisionUs
  double collisionUs = 0.0;  // boxes, broad phase, descent and pair tests
  // Making devices for frame sizes not seen before: a one-off cost of the run (a few
  // microseconds on the CPU, milliseconds for a GL context), left out of frameUs and
  // collisionUs so that times measure collision detection, not start-up.
  double deviceSetupUs = 0.0;
  // What the frame's pair tests handed to the device's hardware and back
  // (raster::TransferCounters): command submissions waited on and bytes read back. Both 0 on
  // the CPU device. Not in `recode run`'s output, which is the same on every exact device.
  long long submissions = 0;
  long long readbackBytes = 0;
  // Compute dispatches recorded for the frame, and the device time of the vulkan-compute
  // device's stages (raster::TransferCounters::kStageNames), from its timestamps; 0 elsewhere.
  long long dispatches = 0;
  std::array<double, raster::TransferCounters::kStages> stageUs{};
  // Of collisionUs, the time the host spent waiting for the device to run what it submitted
  // (raster::TransferCounters::waitUs); the rest is the host's own work. 0 on the CPU device.
  double deviceWaitUs = 0.0;
};

class Simulation {
 public:
  // Builds the object trees. Throws std::invalid_argument when no valid pixel size results.
  Simulation(const Scene& scene, RunOptions options);
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  // Poses the scene at frame k and detects its collisions. Frames may be run in any order
  // (poses are a pure function of k), but the broad phase is fastest frame after frame.
  // Throws std::invalid_argument (naming the frame and pair) when a pair's frame cannot be
  // made, e.g. more than 16384 pixels for a pair at this pixel size.
  [[nodiscard]] FrameReport runFrame(int frame);

  // The objects, posed at the last frame run. runFrame brings every node's OBB up to the pose
  // but makes the AABBs only of the objects whose boxes come near another's (the rest keep
  // those of an earlier frame); updateAllBounds() makes every AABB, for a tool that inspects
  // any two blocks.
  [[nodiscard]] const std::vector<ObjectTree>& objects() const { return objects_; }
  void updateAllBounds();
  [[nodiscard]] double pixelSize() const { return pixelSize_; }
  [[nodiscard]] ViewAxis axis() const { return axis_; }
  [[nodiscard]] ViewAxisRule viewAxisRule() const { return options_.viewAxisRule; }
  [[nodiscard]] PairMode pairMode() const { return options_.pairMode; }
  [[nodiscard]] std::size_t triangleCount() const;  // NTR: triangles of all leaves
  // How many pair tests may run at once (RunOptions::threads resolved; 1 with a factory).
  [[nodiscard]] int threads() const;

  // The frame a leaf pair is drawn in (see above; the screen with RunOptions::drawOnScreen).
  [[nodiscard]] FrameSpec pairFrame(const Aabb& a, const Aabb& b) const;
  // The frame of two leaves: pairFrame of their world AABBs along the axis
  // RunOptions::viewAxisRule chooses for them (the scene's with ViewAxisRule::Scene).
  [[nodiscard]] FrameSpec leafPairFrame(const HierarchyNode& a, const HierarchyNode& b) const;

 private:
  // runFrame's second step: the frame's pair tests from the overlapping object pairs (the
  // descent's box tests counted into `report`); throws past RunOptions::maxPairTestsPerFrame.
  [[nodiscard]] std::vector<PairTask> listPairTasks(
      const std::vector<std::pair<int, int>>& candidates, int frame, FrameReport& report) const;

  std::vector<ObjectTree> objects_;
  RunOptions options_;
  ViewAxis axis_ = ViewAxis::Z;
  double pixelSize_ = 0.0;
  std::optional<FrameSpec> screen_;  // with drawOnScreen
  SweepAndPrune broadPhase_;
  std::unique_ptr<PairTestRunner> pairTests_;    // its devices and threads
  std::unique_ptr<FrameLeafBlocks> leafBlocks_;  // the drawn leaves, kept from frame to frame
  // A device of options_.deviceFactory that reduces the leaves' world boxes where it keeps the
  // blocks (raster::PosedBoxReducer), made at the first frame after the factory made a device
  // for a pair test of that kind; null before, and when there is no factory or its devices
  // cannot: then the host makes the boxes.
  std::unique_ptr<raster::DepthStencilDevice> boxDevice_;
  raster::PosedBoxReducer* boxReducer_ = nullptr;
  bool boxDeviceTried_ = false;
};

// How many pair tests a simulation with these options runs at once: RunOptions::threads with
// 0 resolved to the hardware threads oneTBB sees (and N to at most those), 1 with a
// deviceFactory.
[[nodiscard]] int pairTestThreads(const RunOptions& options);

// The frame of a pair of blocks with world boxes a and b (see above): a window over both boxes
// grown by kDefaultWindowMargin, square pixels of `pixelSize`, the sides rounded up to a
// multiple of kPairFrameGranule pixels about the window's centre. Simulation::pairFrame and the
// collision API (recode/api) draw their pairs in it. Throws std::invalid_argument as
// frameFromPixelSize.
[[nodiscard]] FrameSpec granularPairFrame(ViewAxis axis, double pixelSize, const Aabb& a,
                                          const Aabb& b);

// The pixel size of a run (see above); `bounds` is the objects' box at frame 0.
[[nodiscard]] double runPixelSize(const ViewSpec& view, const Aabb& bounds,
                                  const FrameOverrides& overrides);

}  // namespace recode::core
