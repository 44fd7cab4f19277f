#include "conform/conform_command.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/device_option.hpp"
#include "output/atomic_file.hpp"
#include "recode/conformance/backend.hpp"
#include "recode/conformance/process_backend.hpp"
#include "recode/conformance/reduce.hpp"
#include "recode/conformance/report.hpp"
#include "recode/conformance/suite.hpp"
#include "recode/raster/golden.hpp"

namespace recode::app {

namespace {

namespace fs = std::filesystem;
using namespace recode::conformance;

struct ConformOptions {
  std::string device = "cpu";
  std::string exec;
  std::string golden = RECODE_SOURCE_DATA_DIR "/golden";
  int random = 0;
  std::uint64_t seed = 1;
  std::string family;
  bool keepGoing = false;
  double timeout = 60.0;
  std::string shard;
  std::string baseline, writeBaseline;
  std::string junit, html, reduceDir;
  int repeat = 1;
  std::size_t explain = 4;
  bool json = false;
};

// "I/N" of --shard.
std::pair<int, int> parseShard(const std::string& text) {
  const auto slash = text.find('/');
  int index = -1, count = 0;
  const auto parse = [](std::string_view s, int& v) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
  };
  if (slash == std::string::npos || !parse(std::string_view(text).substr(0, slash), index) ||
      !parse(std::string_view(text).substr(slash + 1), count) || count < 1 || index < 0 ||
      index >= count) {
    throw std::runtime_error("--shard " + text + ": expected I/N with 0 <= I < N, e.g. 0/4");
  }
  return {index, count};
}

// Runs `read` (a library call that reads a file or directory); its std::runtime_error is
// rethrown under `option`, the flag that named the path. A malformed vector's error, which names
// its file, propagates as it is.
template <typename Read>
auto underOption(const char* option, Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const raster::FormatError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(option) + " " + e.what());
  }
}

std::unique_ptr<Backend> makeBackend(const ConformOptions& o) {
  if (!o.exec.empty()) {
    ProcessOptions p;
    p.timeout = std::chrono::milliseconds(static_cast<long long>(o.timeout * 1000.0));
    return std::make_unique<ProcessBackend>(o.exec, p);
  }
  // A device this build cannot make is an error before any vector is read.
  (void)makeNamedDevice(o.device, 1, 1);
  const std::string name = o.device;
  return std::make_unique<DeviceBackend>(
      name, [name](int w, int h) { return makeNamedDevice(name, w, h); });
}

// Reduces the first failing vector of the run and writes the minimal vector and its passing
// twin into the directory.
void reduceFirstFailure(const SuiteReport& report, const std::vector<SuiteVector>& vectors,
                        Backend& backend, const fs::path& dir, std::ostream& out) {
  for (const VectorReport& r : report.vectors) {
    if (r.status != Status::Failed && r.status != Status::ExpectedFailure)
      continue;
    const auto v = std::find_if(vectors.begin(), vectors.end(),
                                [&](const SuiteVector& s) { return s.name == r.name; });
    std::cerr << "recode conform: reducing " << r.name << " ...\n";
    const Reduction red = reduce(v->golden.stream, backend);
    output::CreatedDirectory created(dir, "--reduce");
    std::string stem = fs::path(r.name).stem().string();
    const fs::path minimal = dir / (stem + "-minimal.json");
    output::writeFileAtomically(
        minimal, raster::goldenToJson(red.minimal, raster::GoldenLayout::Rows), "--reduce");
    out << "reduced " << r.name << " in " << red.backendRuns << " runs to " << red.draws
        << " draws, " << red.triangles << " triangles: " << minimal.string() << '\n';
    if (red.passingTwin) {
      const fs::path twin = dir / (stem + "-passing-twin.json");
      output::writeFileAtomically(
          twin, raster::goldenToJson(*red.passingTwin, raster::GoldenLayout::Rows), "--reduce");
      out << "passing twin: " << twin.string() << '\n';
    } else {
      out << "no passing twin: every single step from the minimal vector still fails\n";
    }
    created.keep();
    return;
  }
  out << "--reduce: nothing failed, nothing to reduce\n";
}

// The reports CI reads: the JSON on stdout (--json), the JUnit and HTML files.
void writeReports(const ConformOptions& o, const SuiteReport& report) {
  if (o.json) {
    // Which back end ran: the registry's device, or the command.
    std::cout << toJson(report,
                        {{o.exec.empty() ? "device" : "exec", o.exec.empty() ? o.device : o.exec}});
  }
  if (!o.junit.empty())
    output::writeFileAtomically(o.junit, toJunit(report), "--junit");
  if (!o.html.empty())
    output::writeFileAtomically(o.html, toHtml(report), "--html");
}

// The back end, started; one that breaks the protocol at its greeting still gets the reports
// (the error, its kind, no vectors) before the error ends the command.
std::unique_ptr<Backend> startBackend(const ConformOptions& o) {
  try {
    return makeBackend(o);
  } catch (const BackendError& e) {
    SuiteReport report;
    report.backend = o.exec;
    report.error = e.what();
    report.errorKind = e.kind();
    writeReports(o, report);
    throw;
  }
}

int runConform(const ConformOptions& o) {
  std::vector<SuiteVector> vectors =
      o.random > 0 ? randomVectors(o.random, o.seed, o.family)
                   : underOption("--golden", [&] { return goldenVectors(o.golden); });
  if (!o.shard.empty()) {
    const auto [index, count] = parseShard(o.shard);
    vectors = shardOf(vectors, index, count);
  }
  SuiteOptions options;
  options.repeat = o.repeat;
  options.stopAtFirstFailure = o.random > 0 && !o.keepGoing;
  options.explainLimit = o.json || !o.html.empty() ? 4096 : o.explain;
  if (!o.baseline.empty())
    options.baseline = underOption("--baseline", [&] { return readBaseline(o.baseline); });

  const std::unique_ptr<Backend> backend = startBackend(o);
  const std::string source =
      o.random > 0 ? std::to_string(o.random) + " random streams" +
                         (o.family.empty() ? "" : " of family " + o.family) + " of seed " +
                         std::to_string(o.seed)
                   : std::to_string(vectors.size()) + " golden vectors under " + o.golden;
  if (!o.json) {
    std::cout << "recode conform: " << (o.exec.empty() ? "device " : "back end ") << backend->name()
              << ", " << source << '\n'
              << std::flush;
  }
  const SuiteReport report = runSuite(*backend, vectors, options, [&o](const VectorReport& v) {
    if (!o.json) {
      printVectorLine(std::cout, v);
      std::cout.flush();
    }
  });
  // The failures explained once the run is whole: the reading it names decides their stages.
  if (!o.json && std::any_of(report.vectors.begin(), report.vectors.end(), hasDetails)) {
    std::cout << "\nFailures explained:\n";
    for (const VectorReport& v : report.vectors) {
      if (hasDetails(v))
        printVector(std::cout, v, o.explain);
    }
    std::cout << '\n';
  }
  if (!o.json)
    printSummary(std::cout, report);
  writeReports(o, report);
  if (!report.error.empty()) {
    if (o.json)
      std::cerr << "recode conform: error: " << report.error << '\n';
    return 1;
  }
  if (!o.writeBaseline.empty()) {
    output::writeFileAtomically(o.writeBaseline, toBaseline(report), "--write-baseline");
    const int listed = report.count(Status::Failed) + report.count(Status::ExpectedFailure);
    (o.json ? std::cerr : std::cout)
        << "baseline written to " << o.writeBaseline << ": " << listed << " expected failures\n";
  }
  if (!o.reduceDir.empty())
    reduceFirstFailure(report, vectors, *backend, o.reduceDir, o.json ? std::cerr : std::cout);
  return report.passed() ? 0 : 2;
}

}  // namespace

void addConformCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ConformOptions>();
  CLI::App* cmd = app.add_subcommand(
      "conform",
      "Run the conformance suite on a back end: a device of this build (--device) or a program "
      "in any language speaking the recode-conform-1 line protocol (--exec, docs/conformance.md). "
      "Every depth and stencil value is compared; each failure is explained pixel by pixel and "
      "named. Exit 0: all passed (or failed as the baseline expects); 2: a vector failed; 1: an "
      "error (a back end that crashed, timed out, flooded its answer or broke the protocol: "
      "--json and --junit carry the kind)");
  CLI::Option* device = addDeviceOption(*cmd, o->device, "the device");
  cmd->add_option("--exec", o->exec,
                  "run this command (with /bin/sh -c) as the back end, over the line protocol "
                  "of docs/conformance.md")
      ->excludes(device)
      ->check(CLI::Validator(
          [](const std::string& command) {
            return command.empty() ? std::string("the command is empty") : std::string();
          },
          "COMMAND"));
  CLI::Option* golden =
      cmd->add_option("--golden", o->golden, "directory searched recursively for *.json vectors")
          ->capture_default_str();
  CLI::Option* random =
      cmd->add_option("--random", o->random,
                      "instead of golden vectors, run up to N random streams of the kit's "
                      "families and stop at the first that fails")
          ->check(CLI::Range(1, 1000000))
          ->excludes(golden);
  cmd->add_option("--seed", o->seed, "seed of --random")->capture_default_str()->needs(random);
  cmd->add_option("--family", o->family,
                  "draw every --random stream from this family of the kit (e.g. limits: "
                  "vertices 32768 pixels out)")
      ->needs(random);
  cmd->add_flag("--keep-going", o->keepGoing,
                "run all --random streams instead of stopping at the first that fails (for a "
                "native pipeline: count the departures the graphics APIs forbid)")
      ->needs(random);
  cmd->add_option("--timeout", o->timeout,
                  "seconds --exec's back end may take per answer before the run ends (the kind "
                  "\"timed out\")")
      ->check(CLI::Range(0.001, 86400.0))
      ->capture_default_str();
  cmd->add_option("--shard", o->shard, "run only shard I of N (0-based: every Nth vector from I)");
  cmd->add_option("--baseline", o->baseline,
                  "file of expected failures, one NAME,STAGE a line (kit/slivers_3.json,coverage; "
                  "# comments): a vector that fails at its listed stage does not fail the run; "
                  "one that fails at another stage, or passes, does");
  cmd->add_option("--write-baseline", o->writeBaseline,
                  "write this run's failures with their stages to this file, as --baseline reads "
                  "it (not written when the run ends in an error)");
  cmd->add_option("--repeat", o->repeat,
                  "run every vector this many times (a failing one always twice): different "
                  "answers mark it nondeterministic")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--explain", o->explain, "bad pixels explained per failing vector in the text")
      ->check(CLI::Range(0, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--junit", o->junit,
                  "also write a JUnit XML report to this file: a test case per vector; a back end "
                  "that broke is an error whose type is its kind");
  cmd->add_option("--html", o->html,
                  "also write a self-contained HTML report (error masks, histories) to this file");
  cmd->add_option("--reduce", o->reduceDir,
                  "reduce the first failing vector to a minimal one and write it, with a "
                  "passing twin, as golden vectors into this directory");
  cmd->add_flag("--json", o->json,
                "print one JSON object instead of the report (with error and error_kind when the "
                "back end broke)");
  cmd->callback([o, &exitCode]() { exitCode = runConform(*o); });
}

}  // namespace recode::app
