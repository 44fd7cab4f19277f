#include "pair/pair_command.hpp"

#include <array>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cli/device_option.hpp"
#include "cli/frame_options.hpp"
#include "cli/no_timing.hpp"
#include "cli/pgm.hpp"
#include "cli/view_axis_option.hpp"
#include "pair/pair_report.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/refine/proven_apart.hpp"

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

nlohmann::ordered_json boxJson(const core::Aabb& box) {
  if (box.isEmpty())
    return nullptr;
  return {{box.min.x(), box.min.y(), box.min.z()}, {box.max.x(), box.max.y(), box.max.z()}};
}

// The --mode object: what the adaptive, conservative or skip-apart mode decided, beside the
// reference run's report (which stays as it was).
nlohmann::ordered_json modeJson(core::PairMode mode, raster::DepthStencilDevice& device,
                                const PairSetup& setup, const core::PairRequest& request,
                                const core::PairBlock& a, const core::PairBlock& b,
                                const core::PairResult& reference) {
  nlohmann::ordered_json j;
  j["name"] = core::toString(mode);
  if (mode == core::PairMode::SkipApart) {
    // Proven apart: nothing drawn. Otherwise the skip-apart mode's answer is the reference run's.
    const bool apart = core::provenApart(a, b, request.frame);
    j["verdict"] = apart || !reference.collide ? "apart" : "collide";
    j["proven_apart"] = apart;
    j["interfering_pixels"] = apart ? 0 : reference.interferingPixels;
    return j;
  }
  if (mode == core::PairMode::Conservative) {
    const core::ConservativeResult r = core::collideConservative(device, setup.a, setup.b, request);
    j["verdict"] = r.pair.collide ? "collide" : "apart";
    j["growth"] = {r.growth.x(), r.growth.y(), r.growth.z()};
    j["interfering_pixels"] = r.pair.interferingPixels;
    j["contact_box"] = boxJson(r.pair.contact.box);
    return j;
  }
  core::AdaptivePairTester tester;
  const core::AdaptiveResult r = tester.collide(device, setup.a, setup.b, request);
  j["verdict"] = core::toString(r.verdict);
  j["runs"] = r.runs;
  j["deepest_level"] = r.deepestLevel;
  j["finest_pixel"] = r.finestPixel;
  if (r.contact) {
    const core::FrameSpec& f = r.contactFrame;
    j["contact_frame"] = {{"width", f.width},
                          {"height", f.height},
                          {"window", {f.window.umin, f.window.vmin, f.window.umax, f.window.vmax}}};
    j["interfering_pixels"] = r.contact->interferingPixels;
    j["contact_box"] = boxJson(r.contact->contact.box);
    j["contact_area"] = r.contact->contact.area;
  }
  if (r.verdict == core::PairVerdict::ApartAtLimit)
    j["unresolved_box"] = boxJson(r.unresolved);
  return j;
}

void printMode(std::ostream& out, const nlohmann::ordered_json& j) {
  out << "mode " << j["name"].get<std::string>() << ": " << j["verdict"].get<std::string>();
  for (const char* key :
       {"runs", "deepest_level", "finest_pixel", "interfering_pixels", "proven_apart"})
    if (j.contains(key))
      out << ", " << key << " " << j[key].dump();
  out << '\n';
}

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
  PairSetup setup = loadPairSetup(
      o.scene.empty() ? std::nullopt : std::optional<std::string>(o.scene), o.frame.overrides());
  // Another axis than the scene's: the frame is rebuilt along it at the same pixel size.
  const core::ViewAxisRule axisRule = viewAxisRule(o.viewAxis);
  if (axisRule != core::ViewAxisRule::Scene) {
    core::Aabb bounds = core::boundingBox(setup.a);
    bounds.extend(core::boundingBox(setup.b));
    const core::ViewAxis axis = core::chooseViewAxis(
        axisRule, setup.frame.axis,
        core::axisChoiceInput(setup.a, setup.b, core::framePixelSize(setup.frame)));
    setup.frame = core::frameAlongAxis(setup.frame, axis, bounds);
  }
  core::PairRequest request;
  request.frame = setup.frame;
  request.mor = o.frame.mor();
  request.contact = o.contact;
  request.boxTest = o.boxTest;
  request.normal = o.normal;
  const std::unique_ptr<raster::DepthStencilDevice> device =
      makeNamedDevice(o.device, setup.frame.width, setup.frame.height);
  std::optional<PixelProbe> probe;
  if (!o.pixel.empty()) {
    const auto [x, y] = parsePixel(o.pixel, setup.frame);
    probe.emplace(x, y);
  }
  // Each block with its triangle hierarchy, as a run's leaves have theirs: the pair's time
  // (timing_us) then follows what the MOR covers; building them is not part of it.
  const core::PairBlock a = core::PairBlock::withHierarchy(setup.a);
  const core::PairBlock b = core::PairBlock::withHierarchy(setup.b);
  const core::PairResult result =
      core::collidePair(*device, a, b, request, probe ? &*probe : nullptr);
  if (!o.dumpCases.empty())
    writePgmBottomUp(o.dumpCases, setup.frame.width, setup.frame.height,
                     frameCaseImage(setup.frame, result));
  const core::PairMode mode = *core::parsePairMode(o.mode);
  std::optional<nlohmann::ordered_json> modeReport;
  if (mode != core::PairMode::Reference)
    modeReport = modeJson(mode, *device, setup, request, a, b, result);
  if (o.json) {
    nlohmann::ordered_json j = pairResultToJson(setup, request, result);
    if (modeReport)
      j["mode"] = *modeReport;
    if (axisRule != core::ViewAxisRule::Scene) {
      j["view_axis_rule"] = core::toString(axisRule);
      j["view_axis"] = core::toString(setup.frame.axis);
    }
    if (o.noTiming)
      removeTimingFields(j);
    if (probe)
      j["pixel"] = probe->toJson(result);
    std::cout << j.dump(2) << '\n';
  } else {
    if (axisRule != core::ViewAxisRule::Scene)
      std::cout << "view axis " << core::toString(setup.frame.axis) << " (rule "
                << core::toString(axisRule) << ")\n";
    printPairReport(std::cout, setup, request, result, o.picture);
    if (modeReport)
      printMode(std::cout, *modeReport);
  }
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
                  "with --json: add one pixel's case and its depth and stencil after every step "
                  "(X,Y from the bottom-left, from 0)")
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
