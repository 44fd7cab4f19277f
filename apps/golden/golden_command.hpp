#pragma once
// `recode golden generate`: writes the conformance kit's adversarial golden vectors.

#include <CLI/CLI.hpp>

namespace recode::app {
void addGoldenCommand(CLI::App& app, int& exitCode);
}
