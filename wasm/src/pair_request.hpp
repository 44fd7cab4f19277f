#pragma once
// The module's request: a JSON object naming the options of `recode pair` (docs/wasm.md), read
// into the command's own options so that both run the same code.

#include <string>

#include "pair/pair_run.hpp"

namespace recode::wasm {

struct PairRequestText {
  explain::PairRunOptions options;
  bool timing = true;     // false: the JSON without its wall-clock fields (--no-timing)
  std::string dumpCases;  // --dump-cases: the frame's case map as a PGM file at this path
};

// Reads {"scene", "resolution", "pixel_size", "mor", "contact", "box_test", "normal",
// "pixel", "mode", "view_axis", "timing", "dump_cases"}, every key optional. Throws
// std::invalid_argument naming the key, the value and the rule (an unknown key included).
[[nodiscard]] PairRequestText readPairRequest(const std::string& json);

}  // namespace recode::wasm
