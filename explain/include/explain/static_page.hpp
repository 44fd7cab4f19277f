#pragma once
// The static explain page of one pair: its pictures, index.html and explain.json, as `recode
// explain` writes them (and `--gallery` once per pair).

#include <cstddef>
#include <filesystem>
#include <string>

#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"

namespace recode::explain {

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

}  // namespace recode::explain
