#pragma once
// What `recode run` prints: the per-frame contacts and the run's statistics, as text, JSON
// (docs/cli.md, "recode run") and CSV rows.

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "recode/sim/run_statistics.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::app {

struct RunDescription {
  std::string scene;   // the file or the built-in's name
  std::string source;  // "file" or "built-in"
  int frames = 0;      // frames asked for
  bool stopOnContact = false;
  // --mode: how each leaf pair is decided; a mode other than the reference is named in the
  // header (the reference mode's output is as it always was).
  core::PairMode mode = core::PairMode::Reference;
};

// One frame: {"frame", "pairs": [...], counters, times}.
[[nodiscard]] nlohmann::ordered_json frameToJson(const core::Simulation& sim,
                                                 const core::FrameReport& frame);
// The "stats" object.
// The "stats" object; "pair_tests_skipped" only in the skip-apart mode (here and in every report
// below), so the other modes' reports are as they always were.
[[nodiscard]] nlohmann::ordered_json statisticsToJson(const core::RunStatistics& s,
                                                      core::PairMode mode);
// The top-level keys besides "frames" and "stats".
[[nodiscard]] nlohmann::ordered_json runToJson(const RunDescription& run,
                                               const core::Simulation& sim);

void printRunHeader(std::ostream& out, const RunDescription& run, const core::Simulation& sim);
// The frame's contacts, one line each; nothing for a frame without contact.
void printFrame(std::ostream& out, const core::Simulation& sim, const core::FrameReport& frame);
void printStatistics(std::ostream& out, const core::RunStatistics& s, core::PairMode mode);

[[nodiscard]] std::string csvHeader(core::PairMode mode);
[[nodiscard]] std::string csvRow(const core::FrameReport& frame, core::PairMode mode);

}  // namespace recode::app
