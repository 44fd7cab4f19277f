// recode: the command-line front end of the RECODE reference implementation.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "bench_command.hpp"
#include "conform_command.hpp"
#include "explain_command.hpp"
#include "golden_command.hpp"
#include "pair_command.hpp"
#include "replay_command.hpp"
#include "run_command.hpp"
#include "verify_command.hpp"

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
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "recode: error: " << e.what() << '\n';
    return 1;
  }
  return exitCode;
}
