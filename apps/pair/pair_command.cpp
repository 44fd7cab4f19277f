#include "pair/pair_command.hpp"

#include <iostream>
#include <memory>
#include <string>

#include "cli/device_option.hpp"
#include "cli/frame_options.hpp"
#include "cli/no_timing.hpp"
#include "cli/view_axis_option.hpp"
#include "output/pgm.hpp"
#include "pair/pair_run.hpp"

namespace recode::app {

namespace {

struct PairOptions {
  std::string scene;
  bool json = false;
  bool noTiming = false;  // --no-timing
  FrameOptions frame;
  std::string dumpCases;
  bool contact = true;
  bool boxTest = true;
  bool normal = false;  // --normal
  bool picture = true;
  std::string pixel;               // --pixel X,Y; empty: not given
  std::string mode = "reference";  // --mode
  std::string viewAxis = "scene";  // --view-axis
  std::string device = "cpu";      // --device: a name of the device registry
};

int runPairCommand(const PairOptions& o) {
  explain::PairRunOptions options;
  if (!o.scene.empty())
    options.scene = o.scene;
  options.overrides = o.frame.overrides();
  options.mor = o.frame.mor();
  options.contact = o.contact;
  options.boxTest = o.boxTest;
  options.normal = o.normal;
  options.pixel = o.pixel;
  options.mode = *core::parsePairMode(o.mode);  // CLI11 checked the name
  options.axisRule = viewAxisRule(o.viewAxis);
  const explain::PairRun run = explain::runPair(
      options, [&](int width, int height) { return makeNamedDevice(o.device, width, height); });
  if (!o.dumpCases.empty() && run.layered)
    throw std::invalid_argument(
        "--dump-cases writes RECODE's cases 0-8, which a pair with a closed "
        "mesh does not have (its interference is in --json)");
  if (!o.dumpCases.empty())
    output::writePgmBottomUp(o.dumpCases, run.setup.frame.width, run.setup.frame.height,
                             explain::frameCaseImage(run.setup.frame, run.result));
  if (o.json)
    std::cout << explain::pairRunJson(run, o.noTiming).dump(2) << '\n';
  else
    explain::printPairRun(std::cout, run, o.picture);
  return 0;
}

}  // namespace

void addPairCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<PairOptions>();
  CLI::App* cmd = app.add_subcommand(
      "pair",
      "Run RECODE on the first two objects of a scene (or the built-in pair of cones tip to "
      "tip): the per-pixel cases, the verdict and the contact region");
  cmd->add_option("scene", o->scene,
                  "scene file (JSON, docs/scenes.md); omit for the built-in pair")
      ->check(CLI::ExistingFile);
  CLI::Option* json =
      cmd->add_flag("--json", o->json, "print one JSON object (docs/cli.md) instead of the report");
  addNoTimingFlag(*cmd, json, o->noTiming);
  addFrameOptions(*cmd, o->frame,
                  {"region the passes run over and the stencil is read from: min (the boxes' "
                   "intersection), max (both boxes), full (the frame)",
                   "W or WxH pixels (W alone: square pixels); overrides the scene",
                   "pixel size in world units (square pixels over the window); overrides the "
                   "scene"});
  cmd->add_option("--dump-cases", o->dumpCases,
                  "write each pixel's case (0-8; 255 outside the MOR) as an 8-bit PGM, top row "
                  "first");
  CLI::Option* noContact =
      cmd->add_flag("!--no-contact", o->contact,
                    "skip the two depth passes that measure the overlap (points, box, depth)");
  CLI::Option* normal = cmd->add_flag(
      "--normal", o->normal,
      "also estimate the contact normal (from A towards B) and the penetration depth from the "
      "contact passes' depths (docs/algorithm.md)");
  normal->excludes(noContact);
  cmd->add_flag("!--no-box-test", o->boxTest,
                "run the passes even when the blocks' boxes are apart (shows cases 1, 2, 7, 8)");
  cmd->add_option("--pixel", o->pixel,
                  "with --json: add one pixel's case and its depth and stencil after every step; "
                  "for a pair with a closed mesh, the pixel's entries and exits of each mesh in "
                  "depth order and the sweep's intervals (X,Y from the bottom-left, from 0)")
      ->needs(json);
  cmd->add_flag("!--no-picture", o->picture, "leave the character picture out of the report");
  cmd->add_option(
         "--mode", o->mode,
         "also decide the pair in another mode (docs/algorithm.md, \"Beyond the "
         "paper\"): adaptive (refined on finer frames where a finer grid could change "
         "the answer: collide, apart or apart_at_limit) or conservative (blocks grown "
         "by a pixel: never misses) or skip-apart (the reference, unless the blocks' hulls "
         "are proven apart: then nothing is drawn); the reference report stays as it "
         "is")
      ->check(CLI::IsMember(core::pairModeNames()))
      ->capture_default_str();
  addViewAxisOption(*cmd, o->viewAxis);
  addDeviceOption(*cmd, o->device,
                  "the device the pair is drawn on (an exact one gives the same output bytes "
                  "as cpu, timing aside; the adaptive mode's finer frames are drawn on the CPU "
                  "device)");
  cmd->callback([o, &exitCode]() { exitCode = runPairCommand(*o); });
}

}  // namespace recode::app
