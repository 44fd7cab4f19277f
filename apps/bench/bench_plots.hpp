#pragma once
// The bench's plots: per scene, mean and standard deviation of collision time per frame
// against the scene's triangles, one line per algorithm, drawn by gnuplot (Debian's
// gnuplot-nox) as PNG. The data and script of every plot are kept beside it, so a plot can
// be redrawn or restyled by hand.

#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_experiments.hpp"
#include "bench/bench_runner.hpp"

namespace recode::app {

struct PlotOutcome {
  std::vector<std::filesystem::path> pngs;  // drawn
  std::vector<std::filesystem::path> scripts;
  std::string problem;  // empty when every plot was drawn; else why not (gnuplot missing, ...)
};

// Writes DIR/plots/<experiment>-<scene>.dat and .gp for every scene of the experiments (not
// Table 1, which is a table of counters) and runs gnuplot on each, which draws
// DIR/<experiment>-<scene>.png.
[[nodiscard]] PlotOutcome writeBenchPlots(const std::filesystem::path& dir,
                                          const std::vector<const Experiment*>& experiments,
                                          const std::vector<BenchRow>& rows);

}  // namespace recode::app
