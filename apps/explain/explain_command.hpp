#pragma once
// `recode explain [SCENE.json] --out DIR`: runs RECODE on one pair and writes a picture of
// the buffers after every step, an index.html that walks a student through them, and an
// explain.json that lists the steps, the pictures and the result.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <filesystem>
#include <string>

#include "explain/explain_recorder.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"

namespace recode::app {

using explain::kMaxExplainSide;

struct ExplainSummary {
  core::PairResult result;
  std::size_t pictures = 0;
  std::string thumbnail;  // the case map's picture (the close-up if any), else the silhouettes
};

// Runs the pair with MOR mode `morName` (min, max or full) and writes its pictures,
// index.html and explain.json into the existing directory `dir`. Throws
// std::invalid_argument for a frame over kMaxExplainSide, std::runtime_error for a file.
// `descentHtml`, when not empty, is a section after the first (the box descent of --pair).
ExplainSummary explainPairInto(const PairSetup& setup, const std::string& morName, bool boxTest,
                               const std::filesystem::path& dir,
                               const std::string& descentHtml = {});

void addExplainCommand(CLI::App& app, int& exitCode);

}  // namespace recode::app
