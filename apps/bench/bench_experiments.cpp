// The experiment list of `recode bench`: scenes, tessellation levels, algorithms.
#include "bench/bench_experiments.hpp"

#include "bench/bench_closed.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace recode::app {

namespace {

using Kind = AlgorithmSpec::Kind;

// RECODE on every device (MIN MOR, as `recode run` defaults; Vulkan also test by test instead of
// a frame's tests in one batch), its adaptive, conservative and
// skip-apart modes and its adaptive view axis (`--view-axis adaptive`) on the CPU device, and
// the three peers.
std::vector<AlgorithmSpec> recodeAndPeers() {
  AlgorithmSpec adaptive{"recode-adaptive", Kind::Recode, backends::DeviceKind::Cpu,
                         core::MorMode::Min};
  adaptive.mode = core::PairMode::Adaptive;
  AlgorithmSpec conservative = adaptive;
  conservative.name = "recode-conservative";
  conservative.mode = core::PairMode::Conservative;
  AlgorithmSpec skipApart = adaptive;
  skipApart.name = "recode-skip-apart";
  skipApart.mode = core::PairMode::SkipApart;
  AlgorithmSpec viewAxis{"recode-view-axis", Kind::Recode, backends::DeviceKind::Cpu,
                         core::MorMode::Min};
  viewAxis.viewAxisRule = core::ViewAxisRule::ThinOverlap;
  AlgorithmSpec vulkanPerPair{"recode-vulkan-per-pair", Kind::Recode, backends::DeviceKind::Vulkan,
                              core::MorMode::Min};
  vulkanPerPair.batch = false;
  AlgorithmSpec vulkanSpeculative{"recode-vulkan-speculative", Kind::Recode,
                                  backends::DeviceKind::Vulkan, core::MorMode::Min};
  vulkanSpeculative.contactSchedule = core::ContactSchedule::Speculative;
  AlgorithmSpec vulkanSummaries = vulkanSpeculative;
  vulkanSummaries.name = "recode-vulkan-summaries";
  vulkanSummaries.deviceSummaries = true;
  AlgorithmSpec vulkanWaves = vulkanSummaries;
  vulkanWaves.name = "recode-vulkan-waves";
  vulkanWaves.batchDevicesPerSize = 16;
  return {
      {"recode-cpu", Kind::Recode, backends::DeviceKind::Cpu, core::MorMode::Min},
      adaptive,
      conservative,
      skipApart,
      viewAxis,
      {"recode-gl", Kind::Recode, backends::DeviceKind::Gl, core::MorMode::Min},
      {"recode-gl-exact", Kind::Recode, backends::DeviceKind::GlExact, core::MorMode::Min},
      {"recode-vulkan", Kind::Recode, backends::DeviceKind::Vulkan, core::MorMode::Min},
      vulkanPerPair,
      vulkanSpeculative,
      vulkanSummaries,
      vulkanWaves,
      {"recode-vulkan-32", Kind::Recode, backends::DeviceKind::Vulkan32, core::MorMode::Min},
      {"recode-vulkan-compute", Kind::Recode, backends::DeviceKind::VulkanCompute,
       core::MorMode::Min},
      {"fcl-gjk", Kind::FclGjk},
      {"fcl-obbrss", Kind::FclObbrss},
      {"bullet", Kind::Bullet},
  };
}

// Table 1's columns: the MOR variants on the CPU device.
std::vector<AlgorithmSpec> mors() {
  std::vector<AlgorithmSpec> list;
  for (const auto& [name, mor] :
       {std::pair{"recode-min", core::MorMode::Min}, std::pair{"recode-max", core::MorMode::Max},
        std::pair{"recode-full", core::MorMode::Full}})
    list.push_back({name, Kind::Recode, backends::DeviceKind::Cpu, mor});
  // The paper's FULL: the whole screen read for every pair test.
  AlgorithmSpec screen{"recode-full-screen", Kind::Recode, backends::DeviceKind::Cpu,
                       core::MorMode::Full};
  screen.onScreen = true;
  list.push_back(screen);
  return list;
}

// Closed, non-convex meshes: the layered pair at three resolutions against the peers' mesh
// tests, from about 500 to about 500,000 triangles a mesh.
Experiment closedMeshes() {
  Experiment e{"closed",
               "Closed meshes: the layered pair against the peers' mesh tests",
               closedBenchScenes(),
               {500, 5000, 50000, 500000},
               {500},
               {}};
  for (int width : {128, 256, 512}) {
    AlgorithmSpec layered{"recode-layered-" + std::to_string(width), Kind::RecodeLayered};
    layered.resolution = width;
    e.algorithms.push_back(layered);
  }
  e.algorithms.push_back({"fcl-obbrss", Kind::FclObbrss});
  AlgorithmSpec all{"fcl-obbrss-all", Kind::FclObbrss};
  all.allContacts = true;
  e.algorithms.push_back(all);
  e.algorithms.push_back({"bullet-gimpact", Kind::BulletGImpact});
  e.closedMeshes = true;
  return e;
}

std::vector<Experiment> makeExperiments() {
  std::vector<Experiment> list;
  list.push_back({"table1",
                  "Table 1: MIN, MAX and FULL MOR on hierarchy-9",
                  {"hierarchy-9"},
                  {2880},  // 126,720 triangles; the paper's scene had 126,600
                  {288},
                  mors()});
  // Two hands of 33 blocks and a ball: 56 to 2,304 triangles per block spans the paper's
  // 1,860 to 76,032 triangles.
  list.push_back({"table2",
                  "Table 2: two hands grasping a ball, over tessellation levels",
                  {"hand-grasp"},
                  {56, 128, 256, 512, 1024, 2304},
                  {56},
                  recodeAndPeers()});
  // 100 blocks: 36 to 11,520 triangles per block is the paper's 3,600 to 1,152,000.
  list.push_back({"figure8",
                  "Figure 8: random shapes, 3,600 to 1,152,000 triangles",
                  {"random-shapes"},
                  {36, 144, 576, 2304, 11520},
                  {36},
                  recodeAndPeers()});
  list.push_back({"comb",
                  "The comb experiments: rotation and translation, tips aligned and offset",
                  {"comb-rotate-aligned", "comb-rotate-offset", "comb-translate-aligned",
                   "comb-translate-offset"},
                  {64, 256, 1024, 4096},
                  {64},
                  recodeAndPeers()});
  list.push_back({"random-cones",
                  "100 cones in random motion",
                  {"random-cones"},
                  {16, 64, 256, 1152},
                  {16},
                  recodeAndPeers()});
  list.push_back(closedMeshes());
  return list;
}

std::string experimentNames() {
  std::string names;
  for (const Experiment& e : benchExperiments())
    names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

}  // namespace

const std::vector<Experiment>& benchExperiments() {
  static const std::vector<Experiment> list = makeExperiments();
  return list;
}

std::vector<const Experiment*> selectExperiments(const std::vector<std::string>& names) {
  std::vector<const Experiment*> chosen;
  if (names.empty()) {
    for (const Experiment& e : benchExperiments())
      chosen.push_back(&e);
    return chosen;
  }
  for (const std::string& name : names) {
    const auto& all = benchExperiments();
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const Experiment& e) { return e.name == name; });
    if (it == all.end())
      throw std::invalid_argument("unknown experiment \"" + name +
                                  "\" (experiments: " + experimentNames() + ")");
    if (std::find(chosen.begin(), chosen.end(), &*it) != chosen.end())
      throw std::invalid_argument("experiment \"" + name + "\" is named twice");
    chosen.push_back(&*it);
  }
  return chosen;
}

}  // namespace recode::app
