#pragma once
// What `recode bench` writes: the CSV (one row per scene x tessellation x algorithm; the
// columns are documented in docs/benchmarks.md) and a Markdown summary of the same rows, laid
// out as the paper's tables.

#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_experiments.hpp"
#include "bench/bench_runner.hpp"

namespace recode::app {

// The CSV header line and one line per row (RFC 4180: no field needs quoting, as names are
// built-in identifiers; counters RECODE alone has are empty for the other algorithms).
void writeBenchCsv(std::ostream& out, const std::vector<BenchRow>& rows);

struct BenchContext {
  std::string command;  // the command line that made the rows
  std::string machine;  // CPU model and core count
  std::string compiler;
  bool quick = false;
  int recodeThreads = 1;  // threads of recode-cpu's pair tests (the other columns use one)
};

// Markdown: the context, then per experiment its tables (Table 1: counters and the FULL/MIN
// ratio; the others: mean and standard deviation of collision time, then missed and extra
// pairs against CGAL, per tessellation level and algorithm).
void writeBenchSummary(std::ostream& out, const std::vector<const Experiment*>& experiments,
                       const std::vector<BenchRow>& rows, const BenchContext& context);

// The machine the bench runs on, for the summary: "AMD EPYC, 2 cores".
[[nodiscard]] std::string describeMachine();

}  // namespace recode::app
