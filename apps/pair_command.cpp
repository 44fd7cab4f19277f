#include "pair_command.hpp"

#include <array>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
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
  std::string pixel;  // --pixel X,Y; empty: not given
};

// "X,Y" inside the frame, or std::invalid_argument naming the option, the value and the rule.
std::array<int, 2> parsePixel(const std::string& text, const core::FrameSpec& frame) {
  int x = -1, y = -1;
  char comma = 0;
  std::istringstream in(text);
  const auto bad = [&](const std::string& rule) {
    return std::invalid_argument("--pixel " + text + ": " + rule);
  };
  if (!(in >> x >> comma >> y) || comma != ',' || !(in >> std::ws).eof())
    throw bad("expected X,Y (two whole numbers)");
  if (x < 0 || y < 0 || x >= frame.width || y >= frame.height)
    throw bad("outside the " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
              " frame (x from the left, y from the bottom, from 0)");
  return {x, y};
}

int runPairCommand(const PairOptions& o) {
  const PairSetup setup = loadPairSetup(
      o.scene.empty() ? std::nullopt : std::optional<std::string>(o.scene), o.frame.overrides());
  core::PairRequest request;
  request.frame = setup.frame;
  request.mor = o.frame.mor();
  request.contact = o.contact;
  request.boxTest = o.boxTest;
  raster::CpuDevice device(setup.frame.width, setup.frame.height);
  std::optional<PixelProbe> probe;
  if (!o.pixel.empty()) {
    const auto [x, y] = parsePixel(o.pixel, setup.frame);
    probe.emplace(x, y);
  }
  const core::PairResult result =
      core::collidePair(device, setup.a, setup.b, request, probe ? &*probe : nullptr);
  if (!o.dumpCases.empty())
    writePgmBottomUp(o.dumpCases, setup.frame.width, setup.frame.height,
                     frameCaseImage(setup.frame, result));
  if (o.json) {
    nlohmann::ordered_json j = pairResultToJson(setup, request, result);
    if (o.noTiming)
      removeTimingFields(j);
    if (probe)
      j["pixel"] = probe->toJson(result);
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
  cmd->add_option("--pixel", o->pixel,
                  "with --json: add one pixel's case and its depth and stencil after every step "
                  "(X,Y from the bottom-left, from 0)")
      ->needs(json);
  cmd->add_flag("!--no-picture", o->picture, "leave the character picture out of the report");
  cmd->callback([o, &exitCode]() { exitCode = runPairCommand(*o); });
}

}  // namespace recode::app
