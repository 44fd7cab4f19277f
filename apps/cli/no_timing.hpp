#pragma once
// --no-timing: the --json output of pair, run and verify without its wall-clock fields, so that
// two runs of the same command print the same bytes (to diff, to store as a reference).

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace recode::app {

// The keys that hold wall-clock times, wherever they appear in those outputs: pair's
// timing_us and timing_steps_us; run's frame_us and collision_us per frame and TTF_s, ATF_ms,
// DTF_ms, TTC_s, ATC_ms, DTC_ms in its stats; verify's seconds per oracle. Every other key of
// those outputs is a count or a result, the same on every run.
void removeTimingFields(nlohmann::ordered_json& j);

// Adds --no-timing (which needs --json) to a command.
void addNoTimingFlag(CLI::App& cmd, CLI::Option* json, bool& noTiming);

}  // namespace recode::app
