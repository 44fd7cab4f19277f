// recode: the command-line front end of the RECODE reference implementation.

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "bench/bench_command.hpp"
#include "conform/conform_command.hpp"
#include "explain/explain_command.hpp"
#include "golden/golden_command.hpp"
#include "pair/pair_command.hpp"
#include "recode/io/printable.hpp"
#include "replay/replay_command.hpp"
#include "run/run_command.hpp"
#include "verify/verify_command.hpp"

namespace {

// Standard output is checked like a file: `recode pair --json > /dev/full` must not exit 0
// having written nothing. A write that failed before this flush has left no errno to report.
int checkedStdout(int exitCode) {
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (!std::cout || !flushed || std::ferror(stdout)) {
    std::cerr << "recode: error: writing to standard output failed"
              << (error != 0 ? std::string(" (") + std::strerror(error) + ")" : std::string())
              << '\n';
    return 1;
  }
  return exitCode;
}

// "pair, replay, explain, run, verify, bench": the subcommands in the order --help lists them.
std::string commandList(CLI::App& app) {
  std::string list;
  for (const CLI::App* command : app.get_subcommands({}))
    list += (list.empty() ? "" : ", ") + command->get_name();
  return list;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "recode: image-based collision detection (Baciu, Wong and Sun 1999) on a bit-exact CPU "
      "depth/stencil machine"};
  app.require_subcommand(1);
  int exitCode = 0;
  recode::app::addPairCommand(app, exitCode);
  recode::app::addReplayCommand(app, exitCode);
  recode::app::addExplainCommand(app, exitCode);
  recode::app::addRunCommand(app, exitCode);
  recode::app::addVerifyCommand(app, exitCode);
  recode::app::addBenchCommand(app, exitCode);
  recode::app::addGoldenCommand(app, exitCode);
  recode::app::addConformCommand(app, exitCode);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 says only "A subcommand is required" for `recode frobnicate`: name the word.
    if (argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty()) {
      std::cerr << "recode: unknown command \"" << recode::io::printable(argv[1])
                << "\" (commands: " << commandList(app)
                << ")\nRun with --help for more information.\n";
      return e.get_exit_code();
    }
    return app.exit(e);
  } catch (const std::exception& e) {
    // Messages quote names and text from the user's files: control characters escaped.
    std::cerr << "recode: error: " << recode::io::printable(e.what()) << '\n';
    return 1;
  }
  return checkedStdout(exitCode);
}
