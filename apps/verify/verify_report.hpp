#pragma once
// What `recode verify` prints: a line per pair worth showing and the totals as text, or one
// JSON object (keys in docs/cli.md).

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "recode/refine/view_axis_choice.hpp"
#include "recode/verify/mode_check.hpp"
#include "recode/verify/verify_pair.hpp"
#include "verify/verify_batch.hpp"

namespace recode::app {

struct VerifyRun {
  std::string source;
  verify::OracleSelection oracles;
  backends::GlPlatform glPlatform = backends::GlPlatform::Auto;  // the exact GL device's, resolved
  std::vector<verify::PairVerification> pairs;
  verify::VerificationTotals totals;
  // --modes: the adaptive and conservative modes against CGAL (absent otherwise, so the
  // reference output is unchanged).
  std::optional<verify::ModeCounts> modes;
  std::vector<verify::ModeCheck> modeChecks;  // per pair, with --modes
  // --view-axis other than scene: the rule, each pair's axis and what the choice cost against
  // the scene axis (absent otherwise, so the reference output is unchanged).
  struct ViewAxisTotals {
    core::ViewAxisRule rule = core::ViewAxisRule::Scene;
    std::vector<core::ViewAxis> axes;  // per pair
    std::array<long long, 3> along{};  // pairs drawn along x, y, z
    long long changed = 0;             // pairs drawn along another axis than the scene's
    // Summed over the pairs, in the chosen frames and in the scene's frames (the same run for
    // a pair whose axis did not change).
    long long stencilPixels = 0, sceneStencilPixels = 0;
    double recodeUs = 0.0, sceneRecodeUs = 0.0;
  };
  std::optional<ViewAxisTotals> viewAxis;
  // --gl-exact, --vulkan: every pair again as one batch on that device (verify_batch.hpp).
  std::optional<BatchCheck> glExactBatch;
  std::optional<BatchCheck> vulkanBatch;
};

// The run's verdict, which the report prints and the exit status gives: every pair passed its
// oracles and, with --modes, the modes kept their promises (verify::ModeCounts::promisesHold).
[[nodiscard]] bool verifyRunPassed(const VerifyRun& run);

// Per-pair lines for failing pairs and resolution misses, every pair when `everyPair`; then the
// totals of each oracle that ran and the overall verdict.
void printVerifyReport(std::ostream& out, const VerifyRun& run, bool everyPair);

[[nodiscard]] nlohmann::ordered_json verifyRunToJson(const VerifyRun& run);

}  // namespace recode::app
