#pragma once
// The experiments `recode bench` runs (docs/benchmarks.md): the paper's Table 1, Table 2,
// Figure 8, the comb experiments and the random cones, each as built-in scenes over
// tessellation levels and the algorithms compared on them.

#include <string>
#include <string_view>
#include <vector>

#include "recode/pair/frame.hpp"
#include "recode/refine/pair_mode.hpp"
#include "recode/refine/view_axis_choice.hpp"
#include "recode/verify/recode_detector.hpp"

namespace recode::app {

struct AlgorithmSpec {
  // RecodeLayered, FclObbrss and BulletGImpact on pairs of closed meshes (bench_closed.hpp);
  // the rest on scenes of convex blocks.
  enum class Kind { Recode, RecodeLayered, FclGjk, FclObbrss, Bullet, BulletGImpact };
  std::string name;  // the CSV's `algorithm` column
  Kind kind = Kind::Recode;
  backends::DeviceKind device = backends::DeviceKind::Cpu;  // Recode only
  core::MorMode mor = core::MorMode::Min;                   // Recode only
  bool onScreen = false;  // Recode only: core::RunOptions::drawOnScreen (the paper's screen)
  // Recode only: core::RunOptions::pairMode (recode-adaptive, recode-conservative,
  // recode-skip-apart)
  core::PairMode mode = core::PairMode::Reference;
  // Recode only: core::RunOptions::viewAxisRule (recode-view-axis)
  core::ViewAxisRule viewAxisRule = core::ViewAxisRule::Scene;
  // Recode only: core::RunOptions::batch (off for recode-vulkan-per-pair)
  bool batch = true;
  // Recode only: core::RunOptions::contactSchedule (speculative for recode-vulkan-speculative)
  core::ContactSchedule contactSchedule = core::ContactSchedule::AfterVerdict;
  // Recode only: core::RunOptions::batchDevicesPerSize (16 for recode-vulkan-waves)
  int batchDevicesPerSize = 1;
  // Recode only: core::RunOptions::deviceSummaries (on for recode-vulkan-summaries and -waves)
  bool deviceSummaries = false;
  // RecodeLayered only: pixels across the square frame around both meshes
  int resolution = 0;
  // FclObbrss on closed meshes only: every contact (fcl-obbrss-all) instead of the first
  bool allContacts = false;
};

struct Experiment {
  std::string name;                    // on the command line and in the CSV: "table1", "comb", ...
  std::string title;                   // a heading for the summary
  std::vector<std::string> scenes;     // built-in scene names
  std::vector<int> trianglesPerBlock;  // tessellation levels of a full run
  std::vector<int> quickTrianglesPerBlock;  // of `--quick`
  std::vector<AlgorithmSpec> algorithms;    // CGAL judges them all and is not listed here
  // Pairs of closed meshes along paths (bench_closed.hpp) instead of built-in scenes: `scenes`
  // names the paths and `trianglesPerBlock` is the triangles of each mesh.
  bool closedMeshes = false;
};

// All experiments, in the order they run.
[[nodiscard]] const std::vector<Experiment>& benchExperiments();

// The named experiments in the order given; all of them for an empty list. Throws
// std::invalid_argument for an unknown or repeated name (the message lists the names).
[[nodiscard]] std::vector<const Experiment*> selectExperiments(
    const std::vector<std::string>& names);

// Ground truth: CGAL judges every frame of a scene of at most this many triangles, and every
// kJudgeSampleStep-th frame (0, 10, 20, ...) of a larger one.
inline constexpr long long kJudgeEveryFrameUpTo = 300000;
inline constexpr int kJudgeSampleStep = 10;

}  // namespace recode::app
