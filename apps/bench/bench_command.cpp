#include "bench/bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_experiments.hpp"
#include "bench/bench_plots.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runner.hpp"
#include "cli/progress_bar.hpp"
#include "cli/threads_option.hpp"
#include "output/atomic_file.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"
#include "recode/verify/peer_detectors.hpp"

namespace recode::app {

namespace {

struct BenchOptions {
  std::vector<std::string> experiments;
  bool quick = false;
  std::string out = "recode-bench";
  bool list = false;
  int threads = 0;                      // RECODE's core::RunOptions::threads
  std::vector<std::string> algorithms;  // --algorithms: the columns to run (default: all)
};

struct BenchCase {
  const Experiment* experiment;
  std::string scene;
  int trianglesPerBlock;
};

void printList() {
  std::cout << "experiments (recode bench NAME...; all when none is named):\n";
  for (const Experiment& e : benchExperiments()) {
    std::cout << "  " << e.name << std::string(14 - std::min<std::size_t>(e.name.size(), 12), ' ')
              << e.title << "\n                scenes:";
    for (const std::string& s : e.scenes)
      std::cout << ' ' << s;
    std::cout << "\n                triangles per block:";
    for (int t : e.trianglesPerBlock)
      std::cout << ' ' << t;
    std::cout << " (--quick:";
    for (int t : e.quickTrianglesPerBlock)
      std::cout << ' ' << t;
    std::cout << ")\n                algorithms: cgal (the judge)";
    for (const AlgorithmSpec& a : e.algorithms)
      std::cout << ", " << a.name;
    std::cout << '\n';
  }
}

// The experiments with only the algorithms named by --algorithms (all when none is named).
// Throws std::invalid_argument for a name no selected experiment has, listing theirs.
std::vector<Experiment> keepAlgorithms(const std::vector<const Experiment*>& experiments,
                                       const std::vector<std::string>& names) {
  std::vector<Experiment> kept;
  std::vector<std::string> known;
  for (const Experiment* e : experiments) {
    kept.push_back(*e);
    for (const AlgorithmSpec& a : e->algorithms)
      if (std::find(known.begin(), known.end(), a.name) == known.end())
        known.push_back(a.name);
    if (names.empty())
      continue;
    std::erase_if(kept.back().algorithms, [&](const AlgorithmSpec& a) {
      return std::find(names.begin(), names.end(), a.name) == names.end();
    });
  }
  for (const std::string& name : names) {
    if (std::find(known.begin(), known.end(), name) != known.end())
      continue;
    std::string list;
    for (const std::string& k : known)
      list += (list.empty() ? "" : ", ") + k;
    throw std::invalid_argument("--algorithms: no selected experiment has \"" + name +
                                "\" (they have: " + list + ")");
  }
  return kept;
}

// Every algorithm the bench runs must be in this build: a bench that silently left one out
// would publish a different table under the same name. (--algorithms names a smaller table.)
void requireEverything(const std::vector<Experiment>& experiments) {
  bool peers = false, glDevice = false;
  std::vector<std::string> missing;
  for (const Experiment& e : experiments) {
    for (const AlgorithmSpec& a : e.algorithms) {
      peers = peers || (a.kind != AlgorithmSpec::Kind::Recode &&
                        a.kind != AlgorithmSpec::Kind::RecodeLayered);
      glDevice = glDevice ||
                 (a.kind == AlgorithmSpec::Kind::Recode && a.device == backends::DeviceKind::Gl);
      const backends::DeviceInfo& device = backends::deviceInfo(a.device);
      const std::string what = "the " + std::string(device.name) + " device of " + a.name + " (" +
                               std::string(device.missing) + ")";
      if (a.kind == AlgorithmSpec::Kind::Recode && a.device != backends::DeviceKind::Gl &&
          !device.built && std::find(missing.begin(), missing.end(), what) == missing.end())
        missing.push_back(what);
    }
  }
  if (peers && !verify::peersBuilt())
    missing.emplace_back("the FCL and Bullet peers (RECODE_WITH_PEERS; libfcl-dev, libbullet-dev)");
#if !RECODE_HAVE_CGAL
  missing.emplace_back("the CGAL judge (RECODE_WITH_CGAL; libcgal-dev)");
#endif
#if !RECODE_HAVE_GL_DEVICE
  if (glDevice)
    missing.emplace_back("the GL device (RECODE_WITH_OSMESA or RECODE_WITH_EGL; libosmesa6-dev)");
#endif
  if (missing.empty())
    return;
  std::string what;
  for (const std::string& m : missing)
    what += (what.empty() ? "" : ", ") + m;
  throw std::runtime_error("recode bench needs " + what +
                           ", which this build lacks: run scripts/setup.sh and rebuild, or "
                           "leave those columns out with --algorithms");
}

std::string commandLine(const BenchOptions& o) {
  std::string line = "recode bench";
  for (const std::string& e : o.experiments)
    line += " " + e;
  if (o.quick)
    line += " --quick";
  if (!o.algorithms.empty()) {
    line += " --algorithms ";
    for (std::size_t i = 0; i < o.algorithms.size(); ++i)
      line += (i > 0 ? "," : "") + o.algorithms[i];
  }
  line += " --threads " + std::to_string(o.threads);
  return line + " --out " + o.out;
}

std::string compilerName() {
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "g++ " __VERSION__;
#else
  return "unknown";
#endif
}

std::vector<BenchCase> listCases(const std::vector<const Experiment*>& experiments, bool quick) {
  std::vector<BenchCase> cases;
  for (const Experiment* e : experiments)
    for (const std::string& scene : e->scenes)
      for (int t : quick ? e->quickTrianglesPerBlock : e->trianglesPerBlock)
        cases.push_back({e, scene, t});
  return cases;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs the cases in order, a line each as it ends, under one progress bar for them all.
std::vector<BenchRow> runCases(const std::vector<BenchCase>& cases, int threads) {
  std::vector<BenchRow> rows;
  ProgressBar progress(static_cast<int>(cases.size()) * 1000);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const BenchCase& c = cases[i];
    const auto caseStart = std::chrono::steady_clock::now();
    std::vector<BenchRow> caseRows =
        runBenchCase(*c.experiment, c.scene, c.trianglesPerBlock, threads, [&](double share) {
          progress.update(static_cast<int>(1000.0 * (static_cast<double>(i) + share)));
        });
    const double seconds = secondsSince(caseStart);
    progress.finish();
    std::cout << "[" << i + 1 << "/" << cases.size() << "] " << c.experiment->name << ": "
              << c.scene << ", " << c.trianglesPerBlock << " triangles per block ("
              << caseRows.front().triangles << " triangles): " << std::fixed << std::setprecision(1)
              << seconds << " s\n"
              << std::defaultfloat << std::flush;
    rows.insert(rows.end(), caseRows.begin(), caseRows.end());
  }
  return rows;
}

// Writes summary.md and returns its text, which is also printed.
std::string writeSummary(const std::filesystem::path& path, const BenchOptions& o,
                         const std::vector<const Experiment*>& experiments,
                         const std::vector<BenchRow>& rows) {
  BenchContext context;
  context.command = commandLine(o);
  context.machine = describeMachine();
  context.compiler = compilerName();
  context.quick = o.quick;
  core::RunOptions cpu;
  cpu.threads = o.threads;
  context.recodeThreads = core::pairTestThreads(cpu);
  std::ostringstream summary;
  writeBenchSummary(summary, experiments, rows, context);
  output::writeFileAtomically(path, summary.str());
  return summary.str();
}

int runBench(const BenchOptions& o) {
  if (o.list) {
    printList();
    return 0;
  }
  const std::vector<Experiment> kept =
      keepAlgorithms(selectExperiments(o.experiments), o.algorithms);
  std::vector<const Experiment*> experiments;
  for (const Experiment& e : kept)
    experiments.push_back(&e);
  requireEverything(kept);
  const std::vector<BenchCase> cases = listCases(experiments, o.quick);

  // The output directory is made and bench.csv's temporary created before the first case
  // runs, so that a directory that cannot be written fails at once rather than after the whole
  // bench. A directory made here is removed again if the bench fails.
  const std::filesystem::path dir(o.out);
  output::CreatedDirectory created(dir, "--out " + o.out);
  const std::filesystem::path csvPath = dir / "bench.csv";
  output::AtomicFile csv(csvPath);

  const auto started = std::chrono::steady_clock::now();
  const std::vector<BenchRow> rows = runCases(cases, o.threads);
  std::ostringstream csvText;
  writeBenchCsv(csvText, rows);
  csv.write(csvText.str());
  csv.commit();

  const std::filesystem::path summaryPath = dir / "summary.md";
  const std::string summary = writeSummary(summaryPath, o, experiments, rows);
  const PlotOutcome plots = writeBenchPlots(dir, experiments, rows);
  created.keep();
  const double total = secondsSince(started);
  std::cout << '\n'
            << summary << "\nrecode bench: " << rows.size() << " rows in " << std::fixed
            << std::setprecision(1) << total << " s; wrote " << csvPath.string() << ", "
            << summaryPath.string() << " and " << plots.pngs.size() << " plots\n";
  if (!plots.problem.empty()) {
    std::cerr << "recode bench: warning: plots not drawn: " << plots.problem
              << "; their gnuplot scripts are in " << (dir / "plots").string() << "\n";
  }
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Run the paper's experiments with RECODE (CPU and GL devices), FCL and Bullet on the same "
      "motion paths, judged by CGAL: CSV, a Markdown summary and plots");
  cmd->add_option(
      "experiment", o->experiments,
      "experiments to run: table1, table2, figure8, comb, random-cones, closed (default: all)");
  cmd->add_flag("--quick", o->quick,
                "the smallest tessellation level of each scene only (about a minute)");
  cmd->add_option("--out", o->out, "directory for bench.csv, summary.md and the plots")
      ->capture_default_str();
  cmd->add_flag("--list", o->list, "list the experiments and exit");
  cmd->add_option("--algorithms", o->algorithms,
                  "run only these columns (comma-separated names from --list; the judge always "
                  "runs), e.g. on a machine whose build lacks a device")
      ->delimiter(',');
  addThreadsOption(*cmd, o->threads);
  cmd->callback([o, &exitCode]() { exitCode = runBench(*o); });
}

}  // namespace recode::app
