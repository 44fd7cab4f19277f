#pragma once
// The wall-clock fields of the --json outputs of pair, run and verify, and their removal
// (--no-timing), so that two runs of the same command print the same bytes. No command-line
// parsing here: the WebAssembly module (wasm/) removes them too.

#include <nlohmann/json.hpp>

namespace recode::output {

// The keys that hold wall-clock times, wherever they appear in those outputs: pair's
// timing_us and timing_steps_us; run's frame_us and collision_us per frame and TTF_s, ATF_ms,
// DTF_ms, TTC_s, ATC_ms, DTC_ms in its stats; verify's seconds per oracle. Every other key of
// those outputs is a count or a result, the same on every run.
void removeTimingFields(nlohmann::ordered_json& j);

}  // namespace recode::output
