#include "verify/verify_command.hpp"

#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cli/frame_options.hpp"
#include "cli/no_timing.hpp"
#include "cli/view_axis_option.hpp"
#include "recode/backends/device_registry.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/scene/builtin_scenes.hpp"
#include "recode/verify/exact_parity.hpp"
#include "verify/pair_scenes.hpp"
#include "verify/pair_streams.hpp"
#include "verify/verify_batch.hpp"
#include "verify/verify_pairs.hpp"
#include "verify/verify_report.hpp"

namespace recode::app {

namespace {

struct VerifyOptions {
  std::string scene;
  bool suite = false;
  int count = 504;
  unsigned seed = 20261122;
  int width = 64;
  std::string saveScenes;   // --save-scenes DIR: write the pairs as scenes, check nothing
  std::string saveStreams;  // --save-streams DIR: write the pairs' command streams, check nothing
  bool embree = false;
  bool cgal = false;
  bool gl = false;
  bool glExact = false;
  std::string glPlatform = "auto";
  bool vulkan = false;
  bool vulkan32 = false;       // --vulkan-32: the Vulkan oracle on the 32-bit arithmetic
  bool vulkanCompute = false;  // --vulkan-compute: the Vulkan oracle on the compute device
  bool json = false;
  bool noTiming = false;  // --no-timing
  bool verbose = false;
  bool modes = false;              // --modes
  std::string viewAxis = "scene";  // --view-axis
  FrameOptions frameOptions;
  int frame = 0;
};

// The oracles named on the command line; none named means Embree and CGAL (docs/cli.md,
// "recode verify": the GL replay is asked for explicitly, as it needs OSMesa at run time).
verify::OracleSelection selectedOracles(const VerifyOptions& o) {
  verify::OracleSelection s{o.embree,
                            o.cgal,
                            o.gl,
                            o.glExact,
                            *backends::parseGlPlatform(o.glPlatform),
                            o.vulkan || o.vulkan32 || o.vulkanCompute,
                            o.vulkan32        ? verify::VulkanOracleDevice::Emulated32
                            : o.vulkanCompute ? verify::VulkanOracleDevice::Compute
                                              : verify::VulkanOracleDevice::Native64};
  if (!s.embree && !s.cgal && !s.gl && !s.glExact && !s.vulkan)
    s.embree = s.cgal = true;
  return s;
}

VerifyPairs pairsToVerify(const VerifyOptions& o) {
  if (o.suite)
    return suitePairs(o.count, o.seed, o.width);
  const core::FrameOverrides overrides = o.frameOptions.overrides();
  if (o.scene.empty()) {
    VerifyPairs builtin = scenePairs(core::builtinPairScene(), overrides);
    builtin.source = "built-in pair";
    return builtin;
  }
  return scenePairs(core::loadScene(o.scene), overrides, o.frame);
}

// Counts the pair's axis and what its run cost, beside the same pair drawn in its scene-axis
// frame (run here only when the axis changed; otherwise it is the same run).
void addViewAxisCost(VerifyRun::ViewAxisTotals& v, const core::PairResult& chosen,
                     const core::TriangleMesh& a, const core::TriangleMesh& b,
                     const core::PairRequest& request, const core::FrameSpec& sceneFrame) {
  const core::ViewAxis axis = request.frame.axis;
  v.axes.push_back(axis);
  ++v.along[static_cast<std::size_t>(axis)];
  v.stencilPixels += chosen.stencilPixelsRead;
  v.recodeUs += chosen.timing.totalUs;
  if (axis == sceneFrame.axis) {
    v.sceneStencilPixels += chosen.stencilPixelsRead;
    v.sceneRecodeUs += chosen.timing.totalUs;
    return;
  }
  ++v.changed;
  core::PairRequest sceneRequest = request;
  sceneRequest.frame = sceneFrame;
  raster::CpuDevice device(sceneFrame.width, sceneFrame.height);
  const core::PairResult scene = core::collidePair(device, a, b, sceneRequest);
  v.sceneStencilPixels += scene.stencilPixelsRead;
  v.sceneRecodeUs += scene.timing.totalUs;
}

// The registry's kind of the Vulkan oracle's device.
backends::DeviceKind vulkanDeviceKind(verify::VulkanOracleDevice device) {
  switch (device) {
    case verify::VulkanOracleDevice::Emulated32:
      return backends::DeviceKind::Vulkan32;
    case verify::VulkanOracleDevice::Compute:
      return backends::DeviceKind::VulkanCompute;
    default:
      return backends::DeviceKind::Vulkan;
  }
}

// With --gl-exact or --vulkan, every pair again as one batch on that device, against the
// reference results the oracles judged.
void checkBatches(VerifyRun& run, const VerifyPairs& input,
                  const std::vector<core::PairRequest>& requests) {
  if (!run.oracles.glExact && !run.oracles.vulkan)
    return;
  std::vector<BatchPair> batch;
  for (std::size_t i = 0; i < run.pairs.size(); ++i) {
    const PairToVerify& p = input.pairs[i];
    batch.push_back({&p.label, p.a.get(), p.b.get(), requests[i], &run.pairs[i].result});
  }
  if (run.oracles.glExact)
    run.glExactBatch = checkBatch(batch, verify::glExactDeviceFactory(run.glPlatform));
  if (run.oracles.vulkan)
    run.vulkanBatch = checkBatch(batch, [&](int width, int height) {
      return backends::makeDevice(vulkanDeviceKind(run.oracles.vulkanDevice), width, height);
    });
}

int runVerifyCommand(const VerifyOptions& o) {
  if (!o.saveStreams.empty()) {
    const std::size_t written =
        savePairStreams(pairsToVerify(o), o.frameOptions.mor(), o.saveStreams);
    std::cout << "recode verify --save-streams: wrote " << written << " golden vectors "
              << "(pair-000.json ...) to " << o.saveStreams << '\n';
    return 0;
  }
  if (!o.saveScenes.empty()) {
    const std::size_t written = savePairScenes(pairsToVerify(o), o.saveScenes);
    std::cout << "recode verify --save-scenes: wrote " << written << " scenes (pair-000.json "
              << "...) to " << o.saveScenes << '\n';
    return 0;
  }
  VerifyRun run;
  run.oracles = selectedOracles(o);
  VerifyPairs input = pairsToVerify(o);        // the input's errors first, whatever the build
  verify::PairVerifier verifier(run.oracles);  // throws for an oracle this build lacks
  std::optional<core::AdaptivePairTester> tester;
  if (o.modes) {
    run.modes.emplace();
    tester.emplace();
  }
  if (run.oracles.glExact)
    run.glPlatform = backends::resolveGlPlatform(run.oracles.glPlatform);  // no context: an error
  run.source = input.source;
  const core::ViewAxisRule axisRule = viewAxisRule(o.viewAxis);
  if (axisRule != core::ViewAxisRule::Scene)
    run.viewAxis.emplace().rule = axisRule;
  std::vector<core::PairRequest> requests;  // each pair's, for the batches
  for (PairToVerify& p : input.pairs) {
    core::PairRequest request;
    request.mor = o.frameOptions.mor();
    const core::FrameSpec sceneFrame = p.frame;
    if (run.viewAxis) {
      // The pair's frame rebuilt along the chosen axis at the same pixel size; every oracle
      // and mode then judges that frame.
      core::Aabb bounds = core::boundingBox(*p.a);
      bounds.extend(core::boundingBox(*p.b));
      const core::ViewAxis axis = core::chooseViewAxis(
          axisRule, p.frame.axis, core::axisChoiceInput(*p.a, *p.b, core::framePixelSize(p.frame)));
      p.frame = core::frameAlongAxis(p.frame, axis, bounds);
    }
    request.frame = p.frame;
    try {
      run.pairs.push_back(verifier.verify(p.label, *p.a, *p.b, request));
    } catch (const std::invalid_argument& e) {
      // Name where the failing pair came from: the file (or suite) and its two blocks.
      throw std::invalid_argument(input.source + ": blocks \"" + p.label + "\": " + e.what());
    }
    run.totals.add(run.pairs.back());
    requests.push_back(request);
    if (run.viewAxis)
      addViewAxisCost(*run.viewAxis, run.pairs.back().result, *p.a, *p.b, request, sceneFrame);
    if (run.modes) {
      run.modeChecks.push_back(
          verify::checkModes(*p.a, *p.b, p.frame, run.pairs.back().exact->intersect, *tester));
      run.modes->add(run.modeChecks.back());
    }
  }
  checkBatches(run, input, requests);
  if (o.json) {
    nlohmann::ordered_json j = verifyRunToJson(run);
    if (o.noTiming)
      output::removeTimingFields(j);
    std::cout << j.dump(2) << '\n';
  } else
    printVerifyReport(std::cout, run, o.verbose);
  return verifyRunPassed(run) ? 0 : 2;
}

}  // namespace

void addVerifyCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<VerifyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "verify",
      "Check RECODE against independent oracles: Embree ray casts per pixel, CGAL exact "
      "intersection per pair, the same commands replayed on OpenGL (OSMesa fixed function, or "
      "the exact GL or Vulkan device). Exit status 2 when "
      "anything is unexplained or disagrees");
  auto* scene = cmd->add_option("scene", o->scene,
                                "scene file (JSON, docs/scenes.md): every pair of blocks of "
                                "different objects; omit for the built-in pair")
                    ->check(CLI::ExistingFile);
  auto* suite = cmd->add_flag("--suite", o->suite,
                              "check the generated suite of hard pairs instead of a scene")
                    ->excludes(scene);
  cmd->add_option("--count", o->count, "pairs in the generated suite")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str()
      ->needs(suite);
  cmd->add_option("--seed", o->seed, "seed of the generated suite")
      ->capture_default_str()
      ->needs(suite);
  cmd->add_option("--width", o->width, "frame width in pixels of the generated suite's pairs")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str()
      ->needs(suite);
  cmd->add_option("--save-scenes", o->saveScenes,
                  "write each pair it would check (the suite's, or the scene's block pairs) as "
                  "a scene file that recode pair reads (DIR/pair-NNN.json, its blocks as OFF "
                  "files beside it) and check nothing");
  cmd->add_option("--save-streams", o->saveStreams,
                  "write the command stream of each pair it would check, with the buffers the "
                  "CPU device leaves, as a golden vector (DIR/pair-NNN.json) and check nothing");
  cmd->add_flag("--embree", o->embree,
                "per pixel: Embree ray casts (naming no oracle runs --embree --cgal)");
  CLI::Option* cgalFlag =
      cmd->add_flag("--cgal", o->cgal,
                    "per pair: CGAL exact intersection (naming no oracle runs --embree --cgal)");
  cmd->add_flag("--gl", o->gl,
                "replay every pair's commands on fixed-function OpenGL (OSMesa or EGL: "
                "--gl-platform) and compare the buffers");
  cmd->add_flag("--gl-exact", o->glExact,
                "replay every pair's commands on the exact GL device (shaders, OpenGL 4.5) and "
                "require bit-identical depth and stencil after every command");
  cmd->add_option("--gl-platform", o->glPlatform,
                  "where the GL devices' contexts come from: osmesa, egl, or auto (--gl-exact: "
                  "EGL, else OSMesa; --gl: OSMesa, else EGL)")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}))
      ->capture_default_str();
  CLI::Option* vulkan =
      cmd->add_flag("--vulkan", o->vulkan,
                    "replay every pair's commands on the exact Vulkan device (headless Vulkan 1.3, "
                    "lavapipe or a GPU) and require bit-identical depth and stencil after every "
                    "command");
  cmd->add_flag("--vulkan-32", o->vulkan32,
                "the same on the vulkan-32 device (the exact Vulkan device with 32-bit shader "
                "arithmetic only); reported as \"vulkan\" with \"device\": \"vulkan-32\"")
      ->excludes(vulkan);
  cmd->add_flag("--vulkan-compute", o->vulkanCompute,
                "the same on the vulkan-compute device (the contract as a tile rasterizer in "
                "Vulkan compute shaders); reported as \"vulkan\" with \"device\": "
                "\"vulkan-compute\"")
      ->excludes(vulkan)
      ->excludes("--vulkan-32");
  CLI::Option* json =
      cmd->add_flag("--json", o->json, "print one JSON object (docs/cli.md) instead of the report");
  addNoTimingFlag(*cmd, json, o->noTiming);
  cmd->add_flag("--verbose", o->verbose,
                "list every pair, not only failures, misses and extras within rounding");
  cmd->add_flag("--modes", o->modes,
                "also run the adaptive and conservative modes (docs/algorithm.md, \"Beyond the "
                "paper\") and count their missed and extra pairs against CGAL; needs --cgal. "
                "The verdict is FAILED, exit status 2, also when a mode breaks its promise "
                "(docs/accuracy.md): a conservative miss, a conservative apart where the "
                "reference collides, an extra beyond its bound, or an adaptive definite apart "
                "on a pair that intersects")
      ->needs(cgalFlag);
  addViewAxisOption(*cmd, o->viewAxis);
  const FrameOptionHandles frameOptions =
      addFrameOptions(*cmd, o->frameOptions,
                      {"region the passes run over: min, max, full",
                       "W or WxH pixels for a scene's pairs; overrides the scene",
                       "pixel size in world units for a scene's pairs; overrides the scene"});
  frameOptions.resolution->excludes(suite);
  frameOptions.pixelSize->excludes(suite);
  cmd->add_option("--frame", o->frame, "the scene's frame to pose the objects at (motion)")
      // The frames a scene can run (kMaxFrames); CLI11's NonNegativeNumber printed its upper
      // bound, the largest double, in 309 digits.
      ->check(CLI::Range(0, core::kMaxFrames - 1))
      ->capture_default_str()
      ->excludes(suite);
  cmd->callback([o, &exitCode]() { exitCode = runVerifyCommand(*o); });
}

}  // namespace recode::app
