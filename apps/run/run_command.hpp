#pragma once
#include <CLI/CLI.hpp>

namespace recode::app {
// `recode run SCENE.json|BUILTIN [--frames N] [--stop-on-contact] [--json] [--csv FILE]
//  [--list] [--triangles-per-block N] [--write-scene FILE] [--resolution W[xH] |
//  --pixel-size S] [--mor min|max|full] [--no-contact] [--quiet]`
void addRunCommand(CLI::App& app, int& exitCode);
}  // namespace recode::app
