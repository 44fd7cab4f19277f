// The built-in experiment scenes: the files in data/scenes are the built-ins at their default
// tessellation; each scene has the objects and blocks its description promises; triangle
// budgets give the paper's totals; unknown names and budgets are refused clearly.

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "core_test_support.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/hierarchy.hpp"

using namespace recode::core;
using Catch::Matchers::StartsWith;
using recode::core::test::dataFile;

namespace {

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Census {
  std::size_t objects = 0, blocks = 0, triangles = 0;
};

Census census(const Scene& scene) {
  Census c;
  for (const SceneObject& o : scene.objects) {
    const ObjectTree tree(o);
    ++c.objects;
    c.blocks += tree.leaves().size();
    c.triangles += tree.triangleCount();
  }
  return c;
}

}  // namespace

TEST_CASE("built-in scenes: data/scenes/NAME.json is the built-in", "[builtin]") {
  for (const BuiltinSceneInfo& info : builtinExperimentScenes()) {
    INFO(info.name);
    const std::filesystem::path file = dataFile("scenes/" + std::string(info.name) + ".json");
    REQUIRE(std::filesystem::exists(file));
    const auto expected = nlohmann::json::parse(builtinSceneJson(info.name));
    const auto actual = nlohmann::json::parse(readText(file));
    CHECK(actual == expected);
    // And the file loads as a scene.
    CHECK_NOTHROW(loadScene(file));
  }
}

TEST_CASE("built-in scenes: objects, blocks and frames as described", "[builtin]") {
  for (const char* comb : {"comb-translate-aligned", "comb-translate-offset", "comb-rotate-aligned",
                           "comb-rotate-offset"}) {
    const Scene s = builtinExperimentScene(comb);
    const Census c = census(s);
    CHECK(c.objects == 2);
    CHECK(c.blocks == 10);
    CHECK(c.triangles == 10 * 64);  // 64 triangles per cone by default
    CHECK(s.sourceName == std::string("built-in ") + comb);
  }
  const Census cones = census(builtinExperimentScene("random-cones"));
  CHECK(cones.objects == 100);
  CHECK(cones.blocks == 100);
  const Scene hand = builtinExperimentScene("hand-grasp");
  const Census h = census(hand);
  CHECK(h.objects == 3);          // two hands and the ball
  CHECK(h.blocks == 2 * 16 + 1);  // palm + 5 fingers x 3 phalanges per hand
  const Census nine = census(builtinExperimentScene("hierarchy-9"));
  CHECK(nine.objects == 9);
  CHECK(nine.triangles > 120000);
  CHECK(nine.triangles < 133000);  // "about 126,600"
  CHECK(builtinExperimentScene("hierarchy-9").frames == 36);
}

TEST_CASE("built-in scenes: triangle budgets give the paper's totals", "[builtin]") {
  // random-shapes: 100 objects, 3,600 to 1,152,000 triangles.
  CHECK(census(builtinExperimentScene("random-shapes", 36)).triangles == 3600);
  // hand-grasp: 33 blocks; 2,304 per block is the paper's largest level, 76,032.
  CHECK(census(builtinExperimentScene("hand-grasp", 2304)).triangles == 76032);
  const std::size_t small = census(builtinExperimentScene("hand-grasp", 56)).triangles;
  CHECK(small > 1700);
  CHECK(small < 2000);  // "about 1,860"
}

TEST_CASE("built-in scenes: unknown names and budgets are refused", "[builtin][errors]") {
  CHECK(findBuiltinExperimentScene("hand-grasp") != nullptr);
  CHECK(findBuiltinExperimentScene("hand") == nullptr);
  CHECK_THROWS_WITH(builtinSceneJson("comb-sideways"),
                    StartsWith("unknown built-in scene \"comb-sideways\" (built-ins: "
                               "comb-translate-aligned, comb-translate-offset, "));
  CHECK_THROWS_WITH(builtinExperimentScene("random-cones", 3),
                    "triangles per block 3 is outside 16..100000");
  CHECK_THROWS_AS(builtinSceneJson("random-cones", 100001), std::invalid_argument);
}
