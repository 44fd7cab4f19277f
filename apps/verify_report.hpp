#pragma once
// What `recode verify` prints: a line per pair worth showing and the totals as text, or one
// JSON object (keys in docs/cli.md).

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "recode/verify/mode_check.hpp"
#include "recode/verify/verify_pair.hpp"

namespace recode::app {

struct VerifyRun {
  std::string source;
  verify::OracleSelection oracles;
  verify::GlPlatform glPlatform = verify::GlPlatform::Auto;  // the exact GL device's, resolved
  std::vector<verify::PairVerification> pairs;
  verify::VerificationTotals totals;
  // --modes: the adaptive and conservative modes against CGAL (absent otherwise, so the
  // reference output is unchanged).
  std::optional<verify::ModeCounts> modes;
  std::vector<verify::ModeCheck> modeChecks;  // per pair, with --modes
};

// Per-pair lines for failing pairs and resolution misses, every pair when `everyPair`; then the
// totals of each oracle that ran and the overall verdict.
void printVerifyReport(std::ostream& out, const VerifyRun& run, bool everyPair);

[[nodiscard]] nlohmann::ordered_json verifyRunToJson(const VerifyRun& run);

}  // namespace recode::app
