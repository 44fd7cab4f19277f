#pragma once
// One case of `recode bench`: a built-in scene at one tessellation level. CGAL judges its
// frames first; then every algorithm of the experiment runs the whole motion on the same
// object trees, is timed frame by frame, and is scored against the judge.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_experiments.hpp"
#include "recode/raster/device.hpp"
#include "recode/verify/detection_score.hpp"

namespace recode::app {

// RECODE's own counters, summed over the timed frames (the paper's Table 1).
struct RecodeCounters {
  long long boxTests = 0;
  long long pairTests = 0;
  long long stencilPixelsRead = 0;
  long long depthPixelsRead = 0;
  long long submissions = 0;    // FrameReport::submissions: 0 on the CPU device
  long long readbackBytes = 0;  // FrameReport::readbackBytes
  double deviceWaitUs = 0.0;    // FrameReport::deviceWaitUs
  long long dispatches = 0;     // FrameReport::dispatches
  std::array<double, raster::TransferCounters::kStages> stageUs{};  // FrameReport::stageUs
};

// The layered pair's passes and layers (the closed-mesh experiment), over the timed frames.
struct LayeredCounters {
  long long passes = 0;  // depth/stencil passes drawn, summed
  int layersA = 0;       // the most entries of mesh A at one pixel, over the frames
  int layersB = 0;
};

struct BenchRow {
  std::string experiment;
  std::string scene;
  int trianglesPerBlock = 0;
  long long triangles = 0;  // of the whole scene
  std::string algorithm;    // an AlgorithmSpec's name, or "cgal" for the judge itself
  int frames = 0;           // frames timed (the judge: the frames it judged)
  int judgedFrames = 0;     // frames with a ground truth; missed and extra count on these
  // Collision time per frame, as the detector measures it (scene_detector.hpp).
  double totalMs = 0.0;
  double meanMs = 0.0;
  double sdMs = 0.0;             // population standard deviation over the frames
  long long contacts = 0;        // colliding pairs reported, summed over all timed frames
  verify::DetectionScore score;  // on the judged frames only
  std::optional<RecodeCounters> recode;
  std::optional<LayeredCounters> layered;  // recode-layered-* only
  // recode-adaptive only: pairs recode-cpu missed on the judged frames that this algorithm
  // found (it saw them at finer pixels); nullopt elsewhere or without a recode-cpu row.
  std::optional<long long> seenFiner;
};

// Called with the share of the case done so far, in [0, 1].
using CaseProgress = std::function<void(double)>;

// Runs the case. The judge is "cgal" (verify::makeExactDetector); every algorithm first runs
// frame 0 once untimed (first-touch allocations, lazily built structures), then frames
// 0..F-1 timed. `threads` is RECODE's core::RunOptions::threads (on the CPU device only; the
// judge and the peers are single-threaded). Returns the judge's row followed by one row per
// algorithm.
[[nodiscard]] std::vector<BenchRow> runBenchCase(const Experiment& experiment,
                                                 const std::string& scene, int trianglesPerBlock,
                                                 int threads, const CaseProgress& progress);

// Sets the row's total, mean and standard deviation from its times per frame (microseconds).
void setRowTimes(BenchRow& row, const std::vector<double>& us);

// The frames CGAL judges in a scene of `triangles` triangles run for `frames` frames.
[[nodiscard]] std::vector<int> judgedFrames(long long triangles, int frames);

}  // namespace recode::app
