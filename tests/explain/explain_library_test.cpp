// The explain library's data for the interactive page: the 3-D view's scene (scene_view.hpp)
// and the ray data the exercises check a student's answers against (explain_rays.hpp).
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "explain/explain_rays.hpp"
#include "explain/explain_recorder.hpp"
#include "explain/explain_sections.hpp"
#include "explain/scene_view.hpp"
#include "pair/pair_run.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/scene/scene.hpp"

namespace {

using namespace recode;
using explain::PairSetup;

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Two boxes turned about every axis, seen along `axis`: sloped faces, so the depths vary over
// every pixel, and B's near end inside A.
PairSetup turnedBoxes(const char* axis) {
  const std::string json = std::string(R"({"view": {"axis": ")") + axis +
                           R"(", "resolution": [48, 40]}, "objects": [
      {"name": "A", "shape": {"type": "box", "size": [2, 1.5, 1]}, "position": [0, 0, 0],
       "rotation_deg": [20, 35, 10]},
      {"name": "B", "shape": {"type": "cylinder", "radius": 0.5, "height": 2},
       "position": [0.3, 0.4, 0.2], "rotation_deg": [-15, 5, 40]}]})";
  return explain::pairSetupFromScene(core::parseScene(json, "test scene", "."), {});
}

struct Run {
  core::PairResult result;
  explain::StepRecorder recorder;
};

std::unique_ptr<Run> runRecorded(const PairSetup& setup, core::MorMode mor) {
  auto run = std::make_unique<Run>();
  core::PairRequest request;
  request.frame = setup.frame;
  request.mor = mor;
  raster::CpuDevice device(setup.frame.width, setup.frame.height);
  run->result = core::collidePair(device, setup.a, setup.b, request, &run->recorder);
  return run;
}

}  // namespace

TEST_CASE(
    "the 3-D view's scene, printed and read back as the page does, is the pair the "
    "reference ran",
    "[explain]") {
  for (const char* axis : {"x", "y", "z"}) {
    CAPTURE(axis);
    const PairSetup setup = turnedBoxes(axis);
    const auto run = runRecorded(setup, core::MorMode::Min);
    const nlohmann::json j =
        nlohmann::json::parse(explain::sceneViewJson(setup, run->result).dump());
    CHECK(j["axis"] == axis);
    const core::FrameSpec& f = setup.frame;
    CHECK(j["resolution"] == nlohmann::json{f.width, f.height});
    const std::vector<double> window = j["window"];
    CHECK(sameBits(window[0], f.window.umin));
    CHECK(sameBits(window[3], f.window.vmax));
    const auto range =
        core::pairDepthRange(f.axis, core::boundingBox(setup.a), core::boundingBox(setup.b));
    CHECK(sameBits(j["depth_range"][0].get<double>(), range[0]));
    CHECK(sameBits(j["depth_range"][1].get<double>(), range[1]));
    const raster::PixelRect& m = run->result.mor;
    REQUIRE_FALSE(m.empty());
    CHECK(j["mor"] == nlohmann::json{m.x0, m.y0, m.x1, m.y1});
    REQUIRE(j["blocks"].size() == 2);
    int block = 0;
    for (const core::TriangleMesh* mesh : {&setup.a, &setup.b}) {
      const nlohmann::json& b = j["blocks"][block++];
      const std::vector<double> positions = b["positions"];
      const std::vector<int> triangles = b["triangles"];
      REQUIRE(positions.size() == 3 * mesh->vertexCount());
      REQUIRE(triangles.size() == 3 * mesh->triangleCount());
      int differing = 0;
      for (std::size_t v = 0; v < mesh->vertexCount(); ++v)
        for (int k = 0; k < 3; ++k)
          differing += sameBits(positions[3 * v + k], mesh->vertices[v][k]) ? 0 : 1;
      CHECK(differing == 0);
      for (std::size_t t = 0; t < mesh->triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
          CHECK(triangles[3 * t + k] == static_cast<int>(mesh->triangles[t][k]));
    }
    CHECK(j["blocks"][0]["name"] == setup.nameA);
    CHECK(j["blocks"][1]["name"] == setup.nameB);
  }
}

TEST_CASE(
    "the exercises' answers: at every pixel of the ray data the case is the case of its "
    "face-depth intervals, and the stencil after the fifth pass decodes to it",
    "[explain]") {
  for (const core::MorMode mor : {core::MorMode::Min, core::MorMode::Max}) {
    for (const char* axis : {"x", "z"}) {
      CAPTURE(axis, core::toString(mor));
      const PairSetup setup = turnedBoxes(axis);
      const auto run = runRecorded(setup, mor);
      std::vector<explain::KeptPicture> pictures;  // kept in memory, no file written
      const explain::ExplainedRun explained = explain::explainRun(
          setup, run->result, run->recorder.snapshots(), mor, true, {}, &pictures, {});
      const explain::RayArrays& rays = explained.rays;
      const std::vector<std::string> steps = [&] {
        std::vector<std::string> ids;
        for (const auto& s : rays.scalars["steps"])
          ids.push_back(s["id"]);
        return ids;
      }();
      REQUIRE(steps.size() >= 5);
      REQUIRE(steps[4] == "test_amin_back");
      const auto crop = rays.scalars["crop"];
      const int x0 = crop[0], y0 = crop[1], x1 = crop[2];
      const raster::PixelRect& m = run->result.mor;
      int examined = 0, interfering = 0, outside = 0;
      for (std::size_t i = 0; i < rays.cases.size(); ++i) {
        const int x = x0 + static_cast<int>(i) % (x1 - x0);
        const int y = y0 + static_cast<int>(i) / (x1 - x0);
        CAPTURE(x, y);
        if (x < m.x0 || x >= m.x1 || y < m.y0 || y >= m.y1) {
          ++outside;
          CHECK(rays.cases[i] == -1);
          for (std::size_t k = 0; k < 5; ++k)
            CHECK(rays.stencil[k][i] == 0);  // the scissor kept every pass away
          continue;
        }
        ++examined;
        std::optional<core::DepthInterval> a, b;
        if (rays.coverage[i] & 1u)
          a = core::DepthInterval{rays.aFront[i], rays.aBack[i]};
        if (rays.coverage[i] & 2u)
          b = core::DepthInterval{rays.bFront[i], rays.bBack[i]};
        CHECK(rays.cases[i] == core::caseFromIntervals(a, b));
        CHECK(rays.cases[i] ==
              core::caseFromStencil(static_cast<std::uint8_t>(rays.stencil[4][i])));
        interfering += core::isInterfering(rays.cases[i]) ? 1 : 0;
      }
      CHECK(examined == m.area());
      CHECK(interfering > 0);
      if (mor == core::MorMode::Min)
        CHECK(outside > 0);  // the margin around the MOR
    }
  }
}

TEST_CASE(
    "the steps' names and rules are stated once: the ray data carries every step's, and each "
    "section's heading starts with its step's name",
    "[explain]") {
  const PairSetup setup = turnedBoxes("z");
  const auto run = runRecorded(setup, core::MorMode::Min);
  std::vector<explain::KeptPicture> pictures;
  const explain::ExplainedRun explained = explain::explainRun(
      setup, run->result, run->recorder.snapshots(), core::MorMode::Min, true, {}, &pictures, {});
  const nlohmann::json& words = explained.rays.scalars["step_words"];
  REQUIRE(words.size() == static_cast<std::size_t>(core::kPairStepCount));
  for (int k = 0; k < core::kPairStepCount; ++k) {
    const auto step = static_cast<core::PairStep>(k);
    CAPTURE(k);
    CHECK(words[k]["id"] == std::string(core::toString(step)));
    CHECK(words[k]["name"].get<std::string>().rfind(std::to_string(k + 1) + " ", 0) == 0);
    CHECK(words[k]["rule"].get<std::string>().size() > 40);
  }
  // Each step's operands are what the page can read at a pixel: one of the ray data's arrays
  // (a face depth) or whether A covers the pixel; TestZ compares three depths.
  const nlohmann::json rays = explain::rayDataJson(explained.rays);
  const std::set<std::string> faces = {"a_front", "a_back", "b_front", "b_back"};
  for (const auto& w : words) {
    for (const auto& o : w["operands"]) {
      const std::string name = o.get<std::string>();
      CAPTURE(w["id"], name);
      CHECK((name == "a_covers" || (faces.count(name) == 1 && rays.contains(name))));
    }
  }
  CHECK(words[1]["operands"] == nlohmann::json({"a_back", "b_front", "b_back"}));
  int headed = 0;
  for (const explain::Section& s : explained.sections) {
    for (const auto& w : words) {
      if (w["id"] != s.step)
        continue;
      CAPTURE(s.title);
      CHECK(s.title.rfind(w["name"].get<std::string>() + ": ", 0) == 0);
      ++headed;
    }
  }
  CHECK(headed >= 6);  // the five passes and the read-back at least
}
