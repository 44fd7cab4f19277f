#pragma once
#include <CLI/CLI.hpp>

namespace recode::app {
// `recode bench [EXPERIMENT...] [--quick] [--out DIR] [--list]`: the paper's experiments with
// RECODE (CPU and GL devices) and the FCL and Bullet peers on the same motion paths, judged by
// CGAL; writes DIR/bench.csv, DIR/summary.md and PNG plots (docs/benchmarks.md).
void addBenchCommand(CLI::App& app, int& exitCode);
}  // namespace recode::app
