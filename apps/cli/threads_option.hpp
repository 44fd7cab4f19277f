#pragma once
// --threads N, shared by `recode run` and `recode bench`: the threads a frame's pair tests may
// run on (core::RunOptions::threads; 0 all hardware threads, the default).

#include <CLI/CLI.hpp>

namespace recode::app {

// Adds --threads to `cmd`, writing into `threads` (which must outlive the parse).
CLI::Option* addThreadsOption(CLI::App& cmd, int& threads);

}  // namespace recode::app
