#pragma once
// The options that choose the region and the frame of the pair tests, shared by `recode pair`,
// `recode run` and `recode verify`: --mor, --resolution W[xH] and --pixel-size S (the last two
// exclude each other). Each command gives its own help text, since what the frame covers
// differs between them.

#include <CLI/CLI.hpp>
#include <string>

#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"

namespace recode::app {

struct FrameOptions {
  std::string morName = "min";
  std::string resolution;  // empty: not given
  double pixelSize = 0.0;  // 0: not given

  // The overrides the options give; throws std::invalid_argument for a malformed --resolution.
  [[nodiscard]] core::FrameOverrides overrides() const;
  [[nodiscard]] core::MorMode mor() const;
};

struct FrameOptionHelp {
  std::string mor;
  std::string resolution;
  std::string pixelSize;
};

struct FrameOptionHandles {
  CLI::Option* mor = nullptr;
  CLI::Option* resolution = nullptr;
  CLI::Option* pixelSize = nullptr;
};

// Adds the three options to `cmd`, writing into `values` (which must outlive the parse).
FrameOptionHandles addFrameOptions(CLI::App& cmd, FrameOptions& values,
                                   const FrameOptionHelp& help);

}  // namespace recode::app
