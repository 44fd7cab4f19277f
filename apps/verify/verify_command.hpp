#pragma once
#include <CLI/CLI.hpp>

namespace recode::app {
// `recode verify [SCENE.json] [--suite [--count N] [--seed S] [--width W]] [--embree] [--cgal]
//  [--gl] [--json] [--verbose] [--mor min|max|full] [--resolution W[xH] | --pixel-size S]
//  [--frame K]`
// Exit status 0 when every oracle agrees (up to the counted, explained differences), 2 when
// anything is unexplained or disagrees, 1 on an error.
void addVerifyCommand(CLI::App& app, int& exitCode);
}  // namespace recode::app
