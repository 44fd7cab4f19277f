#pragma once
// `recode conform`: the conformance suite (recode::conformance) on a device of this build or a
// program over the recode-conform-1 protocol, with the options CI needs (baselines, shards,
// JSON, JUnit, HTML, reduction); the library's messages get the flag that named their input.

#include <CLI/CLI.hpp>

namespace recode::app {
// Adds the `conform` subcommand; its run sets `exitCode` (0 passed, 2 a vector failed, 1 error).
void addConformCommand(CLI::App& app, int& exitCode);
}  // namespace recode::app
