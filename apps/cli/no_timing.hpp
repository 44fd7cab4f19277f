#pragma once
// --no-timing: the --json output of pair, run and verify without its wall-clock fields
// (cli/timing_fields.hpp), so that two runs of the same command print the same bytes.

#include <CLI/CLI.hpp>

#include "output/timing_fields.hpp"

namespace recode::app {

// Adds --no-timing (which needs --json) to a command.
void addNoTimingFlag(CLI::App& cmd, CLI::Option* json, bool& noTiming);

}  // namespace recode::app
