// RECODE behind the bench's detector interface: the same pairs as the simulation's contacts,
// sorted, with leaf node indices; and on the GL device (when built) the same pairs as on the
// CPU reference over a whole built-in motion.

#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "detector_test_support.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"
#include "recode/verify/recode_detector.hpp"

using namespace recode;
using test::treesOf;
using verify::LeafPairId;

TEST_CASE("RecodeDetector reports the simulation's contacts as sorted leaf pairs",
          "[bench][recode]") {
  const core::Scene scene = core::builtinExperimentScene("hierarchy-9", 288);
  verify::RecodeDetector detector(scene, core::RunOptions{}, backends::DeviceKind::Cpu,
                                  "recode-cpu");
  core::Simulation reference(scene, core::RunOptions{});
  std::vector<core::ObjectTree> trees = treesOf(scene);
  long long pairs = 0;
  for (int k = 0; k < scene.frames.value_or(core::kDefaultRunFrames); ++k) {
    for (core::ObjectTree& t : trees)
      t.setFrame(k);
    const verify::Detection d = detector.detect(trees, k);
    const core::FrameReport r = reference.runFrame(k);
    INFO("frame " << k);
    REQUIRE(d.pairs.size() == r.contacts.size());
    CHECK(std::is_sorted(d.pairs.begin(), d.pairs.end()));
    for (const core::LeafContact& c : r.contacts)
      CHECK(std::find(d.pairs.begin(), d.pairs.end(),
                      LeafPairId{c.objectA, c.leafA, c.objectB, c.leafB}) != d.pairs.end());
    test::checkPairsAreLeafPairs(trees, d.pairs);
    CHECK(detector.lastReport().pairTests == r.pairTests);
    CHECK(d.collisionUs >= 0.0);
    pairs += static_cast<long long>(d.pairs.size());
  }
  CHECK(pairs > 0);
}

#if RECODE_HAVE_GL_DEVICE
TEST_CASE("RECODE on the GL device finds the CPU reference's pairs on whole motions",
          "[bench][recode][gl]") {
  const auto name = GENERATE("comb-translate-aligned", "hierarchy-9");
  const core::Scene scene = core::builtinExperimentScene(name, 64);
  verify::RecodeDetector cpu(scene, core::RunOptions{}, backends::DeviceKind::Cpu, "recode-cpu");
  verify::RecodeDetector gl(scene, core::RunOptions{}, backends::DeviceKind::Gl, "recode-gl");
  std::vector<core::ObjectTree> trees = treesOf(scene);
  long long pairs = 0;
  for (int k = 0; k < scene.frames.value_or(core::kDefaultRunFrames); ++k) {
    for (core::ObjectTree& t : trees)
      t.setFrame(k);
    INFO(name << ", frame " << k);
    const verify::Detection a = cpu.detect(trees, k);
    const verify::Detection b = gl.detect(trees, k);
    CHECK(a.pairs == b.pairs);
    CHECK(cpu.lastReport().stencilPixelsRead == gl.lastReport().stencilPixelsRead);
    pairs += static_cast<long long>(a.pairs.size());
  }
  CHECK(pairs > 0);
}
#else
TEST_CASE("RECODE on the GL device is refused without OSMesa", "[bench][recode][gl]") {
  const core::Scene scene = core::builtinExperimentScene("comb-translate-aligned", 64);
  CHECK_THROWS_AS(verify::RecodeDetector(scene, core::RunOptions{}, backends::DeviceKind::Gl, "gl"),
                  std::runtime_error);
}
#endif
