#pragma once
// `recode demo`: the CPU depth/stencil machine running RECODE's first two passes on two cones
// tip to tip, printed as numbers and as a picture of the stencil buffer.

#include <CLI/CLI.hpp>

namespace recode::app {
void addDemoCommand(CLI::App& app, int& exitCode);
}
