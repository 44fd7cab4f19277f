#pragma once
// `recode replay`: runs a golden vector or command-stream file on the CPU device.

#include <CLI/CLI.hpp>

namespace recode::app {
void addReplayCommand(CLI::App& app, int& exitCode);
}
