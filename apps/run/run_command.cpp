#include "run/run_command.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cli/device_option.hpp"
#include "cli/frame_options.hpp"
#include "cli/no_timing.hpp"
#include "cli/progress_bar.hpp"
#include "cli/streamed_json.hpp"
#include "cli/threads_option.hpp"
#include "cli/view_axis_option.hpp"
#include "output/atomic_file.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/scene/scene.hpp"
#include "recode/sim/run_statistics.hpp"
#include "recode/sim/simulation.hpp"
#include "run/run_report.hpp"

namespace recode::app {

namespace {

struct RunOptions {
  std::string scene;
  int frames = 0;  // 0: the scene's, else kDefaultRunFrames
  bool stopOnContact = false;
  bool json = false;
  bool noTiming = false;  // --no-timing
  std::string csv;
  bool list = false;
  int trianglesPerBlock = 0;  // 0: the built-in's default
  std::string writeScene;
  FrameOptions frame;
  bool contact = true;
  bool quiet = false;
  int threads = 0;  // core::RunOptions::threads
  long long maxPairTests = core::kDefaultMaxPairTestsPerFrame;
  std::string mode = "reference";                 // --mode
  std::string viewAxis = "scene";                 // --view-axis
  std::string device = "cpu";                     // --device: a name of the device registry
  bool perPair = false;                           // --per-pair: core::RunOptions::batch off
  std::string contactSchedule = "after-verdict";  // --contact-schedule
  int batchDevices = 1;                           // --batch-devices
  bool summaries = false;                         // --summaries
  std::string leafBoxes = "device";               // --leaf-boxes
};

std::string builtinNames() {
  std::string names;
  for (const core::BuiltinSceneInfo& b : core::builtinExperimentScenes())
    names += (names.empty() ? "" : ", ") + std::string(b.name);
  return names;
}

void printList() {
  std::cout << "built-in scenes (recode run NAME; --triangles-per-block N to change the "
               "tessellation):\n";
  for (const core::BuiltinSceneInfo& b : core::builtinExperimentScenes())
    std::cout << "  " << b.name << std::string(24 - std::min<std::size_t>(b.name.size(), 22), ' ')
              << b.summary << " (default " << b.defaultTrianglesPerBlock
              << " triangles per block)\n";
}

// o.scene as a file or a built-in, after refusing a name that is neither and the options that
// do not apply to its kind.
struct SceneChoice {
  bool isFile = false;
  std::optional<int> triangles;  // --triangles-per-block, for a built-in
};

SceneChoice chooseScene(const RunOptions& o) {
  if (o.scene.empty())
    throw std::invalid_argument("give a scene file or a built-in scene (" + builtinNames() +
                                "), or --list");
  const std::optional<int> triangles =
      o.trianglesPerBlock > 0 ? std::optional<int>(o.trianglesPerBlock) : std::nullopt;
  std::error_code ec;
  const bool isFile = std::filesystem::exists(o.scene, ec);
  const bool isBuiltin = !isFile && core::findBuiltinExperimentScene(o.scene) != nullptr;
  const bool looksLikeFile = o.scene.find('/') != std::string::npos || o.scene.ends_with(".json");
  if (!isFile && !isBuiltin && looksLikeFile)
    (void)core::loadScene(o.scene);  // throws its "cannot open scene file (...)" error
  if (!isFile && !isBuiltin) {
    throw std::invalid_argument(
        "'" + o.scene +
        "' is neither a scene file nor a built-in scene (built-ins: " + builtinNames() + ")");
  }
  if (isFile && triangles)
    throw std::invalid_argument("--triangles-per-block applies to built-in scenes only; '" +
                                o.scene + "' is a file");
  if (!o.writeScene.empty() && !isBuiltin)
    throw std::invalid_argument("--write-scene writes a built-in scene; '" + o.scene +
                                "' is a file");
  return {isFile, triangles};
}

// Runs the frames, each reported as the options ask, up to the first contact with
// --stop-on-contact; under --json each frame's object goes to `json` as soon as it is done.
core::RunStatistics runFrames(const RunOptions& o, int frameCount, core::Simulation& sim,
                              output::AtomicFile* csv, StreamedJsonObject* json) {
  core::RunStatisticsAccumulator stats;
  ProgressBar progress(frameCount);
  for (int k = 0; k < frameCount; ++k) {
    const core::FrameReport report = sim.runFrame(k);
    stats.add(report);
    if (csv)
      csv->write(csvRow(report, sim.pairMode()));
    if (json) {
      nlohmann::ordered_json frame = frameToJson(sim, report);
      if (o.noTiming)
        output::removeTimingFields(frame);
      json->add(frame);
    } else if (!o.quiet)
      printFrame(std::cout, sim, report);
    progress.update(k + 1);
    if (o.stopOnContact && !report.contacts.empty())
      break;
  }
  progress.finish();
  return stats.result(static_cast<long long>(sim.triangleCount()));
}

// The simulation, its frame errors naming where the pixel size came from (as pair's).
core::Simulation makeSimulation(const RunOptions& o, const core::Scene& scene,
                                const core::RunOptions& options) {
  try {
    return core::Simulation(scene, options);
  } catch (const std::invalid_argument& e) {
    if (o.frame.pixelSize == 0.0 && o.frame.resolution.empty())
      throw core::SceneError(scene.sourceName.empty() ? o.scene : scene.sourceName, "view",
                             e.what());
    throw std::invalid_argument(
        std::string(o.frame.resolution.empty() ? "--pixel-size: " : "--resolution: ") + e.what());
  }
}

void simulate(const RunOptions& o, const core::Scene& scene, bool isFile) {
  core::RunOptions options;
  options.overrides = o.frame.overrides();
  options.mor = o.frame.mor();
  options.contact = o.contact;
  options.threads = o.threads;
  options.maxPairTestsPerFrame = o.maxPairTests;
  options.keepContactPoints = false;                // the report prints counts, area and box only
  options.pairMode = *core::parsePairMode(o.mode);  // CLI11 checked the name
  options.viewAxisRule = viewAxisRule(o.viewAxis);
  options.deviceFactory = namedDeviceFactory(o.device);
  options.batch = !o.perPair;
  options.contactSchedule = o.contactSchedule == "speculative"
                                ? core::ContactSchedule::Speculative
                                : core::ContactSchedule::AfterVerdict;
  options.batchDevicesPerSize = o.batchDevices;
  options.deviceSummaries = o.summaries;
  options.leafBoxesOnDevice = o.leafBoxes == "device";
  core::Simulation sim = makeSimulation(o, scene, options);

  RunDescription run;
  run.scene = o.scene;
  run.source = isFile ? "file" : "built-in";
  run.frames = o.frames > 0 ? o.frames : scene.frames.value_or(core::kDefaultRunFrames);
  run.stopOnContact = o.stopOnContact;
  run.mode = options.pairMode;

  // Written beside the target and renamed at the end: a run that fails midway leaves no
  // partial CSV (and an earlier one as it was).
  std::optional<output::AtomicFile> csv;
  if (!o.csv.empty()) {
    csv.emplace(o.csv, "--csv " + o.csv);
    csv->write(csvHeader(options.pairMode));
  }
  // The JSON object is printed frame by frame (the bytes of dumping it whole): a run's memory
  // follows its largest frame, not its length. A run that fails midway has printed a prefix and
  // exits non-zero.
  std::optional<StreamedJsonObject> json;
  if (o.json) {
    nlohmann::ordered_json head = runToJson(run, sim);
    if (o.noTiming)
      output::removeTimingFields(head);
    json.emplace(std::cout, head, "frames");
  } else {
    printRunHeader(std::cout, run, sim);
  }
  core::RunStatistics result;
  try {
    result = runFrames(o, run.frames, sim, csv ? &*csv : nullptr, json ? &*json : nullptr);
  } catch (const std::invalid_argument& e) {
    // A frame's error names the frame and blocks; the scene it came from is added here.
    throw std::invalid_argument(o.scene + ": " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(o.scene + ": " + e.what());
  }
  if (json) {
    nlohmann::ordered_json tail;
    tail["stats"] = statisticsToJson(result, options.pairMode);
    if (o.noTiming)
      output::removeTimingFields(tail);
    json->finish(tail);
  } else {
    printStatistics(std::cout, result, options.pairMode);
  }
  if (csv)
    csv->commit();
}

int runRunCommand(const RunOptions& o) {
  if (o.list) {
    printList();
    return 0;
  }
  const SceneChoice choice = chooseScene(o);
  if (!o.writeScene.empty()) {
    output::writeFileAtomically(o.writeScene, core::builtinSceneJson(o.scene, choice.triangles),
                                "--write-scene " + o.writeScene);
    std::cerr << "recode run: wrote " << o.scene << " to " << o.writeScene << "\n";
    return 0;
  }
  simulate(o,
           choice.isFile ? core::loadScene(o.scene)
                         : core::builtinExperimentScene(o.scene, choice.triangles),
           choice.isFile);
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Simulate a scene (a file or a built-in experiment) over frames: per frame the "
      "interfering blocks and their contact regions, then the paper's Table 2 statistics");
  cmd->add_option("scene", o->scene, "scene file (JSON, docs/scenes.md) or built-in scene name");
  cmd->add_option("--frames", o->frames,
                  "frames to run (default: the scene's \"frames\", else 100)")
      ->check(CLI::Range(1, core::kMaxFrames));
  cmd->add_flag("--stop-on-contact", o->stopOnContact, "stop after the first frame with contact");
  CLI::Option* json =
      cmd->add_flag("--json", o->json, "print one JSON object (docs/cli.md) instead of the report");
  addNoTimingFlag(*cmd, json, o->noTiming);
  cmd->add_option("--csv", o->csv, "write one CSV row of times and counters per frame to FILE");
  cmd->add_flag("--list", o->list, "list the built-in scenes and exit");
  cmd->add_option("--triangles-per-block", o->trianglesPerBlock,
                  "tessellate every block of a built-in scene to about N triangles")
      ->check(CLI::Range(core::kMinTrianglesPerBlock, core::kMaxTrianglesPerBlock));
  cmd->add_option("--write-scene", o->writeScene,
                  "write the built-in scene as a scene file (JSON) to FILE and exit");
  addFrameOptions(*cmd, o->frame,
                  {"MOR of every pair test: min, max or full",
                   "W or WxH pixels of the scene's screen, which sets the pixel size; overrides "
                   "the scene",
                   "pixel size in world units; overrides the scene"});
  cmd->add_flag("!--no-contact", o->contact,
                "skip the two depth passes that measure each contact region");
  cmd->add_flag("--quiet", o->quiet, "print only the header and the statistics");
  addThreadsOption(*cmd, o->threads);
  addDeviceOption(*cmd, o->device,
                  "the device the pairs are drawn on (an exact one gives the same output bytes "
                  "as cpu, timing aside; a GPU-API device draws from one thread, whatever "
                  "--threads says)");
  CLI::Option* perPair = cmd->add_flag(
      "--per-pair", o->perPair,
      "on a device that defers its commands (vulkan, gl-exact), run each pair test on "
      "its own instead of a frame's tests as one batch (one or two submissions a "
      "frame): the same output, for comparing the two");
  cmd->add_option("--contact-schedule", o->contactSchedule,
                  "on a device that defers its commands, when a batch draws its contact passes: "
                  "after-verdict (after the stencil's verdict, for the pairs that interfere: two "
                  "submissions a frame) or speculative (over every pair's MOR with the stencil "
                  "passes: one submission, more pixels); the same output")
      ->check(CLI::IsMember({"after-verdict", "speculative"}))
      ->excludes(perPair)
      ->capture_default_str();
  cmd->add_flag("--summaries", o->summaries,
                "on a device that defers its commands, conclude each pair test from the device's "
                "64-byte summaries of its buffers, made by a compute shader on vulkan, vulkan-32 "
                "and gl-exact, instead of reading the stencil and depths back; the same output")
      ->excludes(perPair);
  cmd->add_option("--batch-devices", o->batchDevices,
                  "on a device that defers its commands, up to N devices of each pair frame size, "
                  "so that a frame's pair tests are recorded in waves of pairs on devices of "
                  "their own (on Vulkan one barrier a wave, not one a pair); the same output")
      ->check(CLI::Range(1, core::kMaxBatchDevicesPerSize))
      ->excludes(perPair)
      ->capture_default_str();
  cmd->add_option("--leaf-boxes", o->leafBoxes,
                  "where the leaves' world boxes are made each frame: device (on a device that "
                  "keeps the blocks, vulkan-compute: one submission more a frame, no vertex "
                  "mapped on the host; elsewhere the host) or host; the same output")
      ->check(CLI::IsMember({"device", "host"}))
      ->capture_default_str();
  addViewAxisOption(*cmd, o->viewAxis);
  cmd->add_option("--max-pair-tests", o->maxPairTests,
                  "stop with an error when a frame lists more than N pair tests (default " +
                      std::to_string(core::kDefaultMaxPairTestsPerFrame) +
                      "): a frame holds its tests at once")
      ->check(CLI::Range(1LL, core::kMaxPairTestsPerFrameLimit));
  cmd->add_option("--mode", o->mode,
                  "how each block pair is decided (docs/algorithm.md, \"Beyond the paper\"): "
                  "reference (the paper's algorithm), adaptive (refined on finer frames where "
                  "a finer grid could change the answer), conservative (blocks grown by a "
                  "pixel: never misses, may report blocks a pixel apart) or skip-apart (the "
                  "reference's contacts; pairs whose hulls are proven apart are not drawn)")
      ->check(CLI::IsMember(core::pairModeNames()))
      ->capture_default_str();
  cmd->callback([o, &exitCode]() { exitCode = runRunCommand(*o); });
}

}  // namespace recode::app
