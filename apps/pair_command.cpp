#include "pair_command.hpp"

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "frame_options.hpp"
#include "no_timing.hpp"
#include "pair_report.hpp"
#include "pair_setup.hpp"
#include "pgm.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"

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
  bool picture = true;
};

int runPairCommand(const PairOptions& o) {
  const PairSetup setup = loadPairSetup(
      o.scene.empty() ? std::nullopt : std::optional<std::string>(o.scene), o.frame.overrides());
  core::PairRequest request;
  request.frame = setup.frame;
  request.mor = o.frame.mor();
  request.contact = o.contact;
  request.boxTest = o.boxTest;
  raster::CpuDevice device(setup.frame.width, setup.frame.height);
  // Each block with its triangle hierarchy, as a run's leaves have theirs: the pair's time
  // (timing_us) then follows what the MOR covers; building them is not part of it.
  const core::PairBlock a = core::PairBlock::withHierarchy(setup.a);
  const core::PairBlock b = core::PairBlock::withHierarchy(setup.b);
  const core::PairResult result = core::collidePair(device, a, b, request);
  if (!o.dumpCases.empty())
    writePgmBottomUp(o.dumpCases, setup.frame.width, setup.frame.height,
                     frameCaseImage(setup.frame, result));
  if (o.json) {
    nlohmann::ordered_json j = pairResultToJson(setup, request, result);
    if (o.noTiming)
      removeTimingFields(j);
    std::cout << j.dump(2) << '\n';
  } else
    printPairReport(std::cout, setup, request, result, o.picture);
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
  cmd->add_flag("!--no-contact", o->contact,
                "skip the two depth passes that measure the overlap (points, box, depth)");
  cmd->add_flag("!--no-box-test", o->boxTest,
                "run the passes even when the blocks' boxes are apart (shows cases 1, 2, 7, 8)");
  cmd->add_flag("!--no-picture", o->picture, "leave the character picture out of the report");
  cmd->callback([o, &exitCode]() { exitCode = runPairCommand(*o); });
}

}  // namespace recode::app
