#pragma once
#include <CLI/CLI.hpp>

namespace recode::app {
// `recode pair [SCENE.json] [--json] [--mor min|max|full] [--resolution W[xH]]
//  [--pixel-size S] [--dump-cases FILE.pgm] [--no-contact] [--no-box-test] [--no-picture]`
void addPairCommand(CLI::App& app, int& exitCode);
}  // namespace recode::app
