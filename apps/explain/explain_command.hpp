#pragma once
// `recode explain [SCENE.json] --out DIR`: runs RECODE on one pair and writes a picture of
// the buffers after every step, an index.html that walks a student through them, and an
// explain.json that lists the steps, the pictures and the result.

#include <CLI/CLI.hpp>

namespace recode::app {

void addExplainCommand(CLI::App& app, int& exitCode);

}  // namespace recode::app
