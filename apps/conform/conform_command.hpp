#pragma once
// `recode conform`: replays every golden vector under a directory on a chosen device and
// reports each one's pass or fail with its first differing pixel.

#include <CLI/CLI.hpp>

namespace recode::app {
void addConformCommand(CLI::App& app, int& exitCode);
}
