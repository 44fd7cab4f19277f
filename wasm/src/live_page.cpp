#include "live_page.hpp"

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "explain/explain_page.hpp"
#include "explain/explain_rays.hpp"
#include "explain/explain_recorder.hpp"
#include "explain/explain_sections.hpp"
#include "explain/scene_view.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::wasm {

LivePage livePage(const PairRequestText& request) {
  explain::StepRecorder recorder;
  const explain::PairRun run = explain::runPair(
      request.options,
      [](int width, int height) {
        if (width > explain::kMaxExplainSide || height > explain::kMaxExplainSide)
          throw std::invalid_argument("the frame is " + std::to_string(width) + "x" +
                                      std::to_string(height) + "; the page draws at most " +
                                      std::to_string(explain::kMaxExplainSide) +
                                      " pixels a side (choose a smaller resolution)");
        return std::make_unique<raster::CpuDevice>(width, height);
      },
      &recorder);
  if (run.layered)
    throw std::invalid_argument(
        "the page shows RECODE's passes on two convex blocks; this pair "
        "has a closed mesh (recode pair decides it by layers)");
  const explain::PairSetup& setup = run.setup;
  LivePage page;
  const explain::ExplainedRun explained =
      explain::explainRun(setup, run.result, recorder.snapshots(), run.request.mor,
                          run.request.boxTest, {}, &page.pictures, {});
  const explain::RayArrays& arrays = explained.rays;
  // One block of numbers, in the order of "ray_arrays" below: the page makes typed arrays of
  // it instead of reading hundreds of thousands of numbers as JSON.
  for (const auto& step : arrays.depth)
    page.rays.insert(page.rays.end(), step.begin(), step.end());
  for (const auto& step : arrays.stencil)
    page.rays.insert(page.rays.end(), step.begin(), step.end());
  for (const auto* a :
       {&arrays.aFront, &arrays.aBack, &arrays.bFront, &arrays.bBack, &arrays.coverage})
    page.rays.insert(page.rays.end(), a->begin(), a->end());
  page.rays.insert(page.rays.end(), arrays.cases.begin(), arrays.cases.end());
  const explain::Page shown{setup,          std::string(core::toString(run.request.mor)),
                            run.result,     explained.scale,
                            explained.view, explained.sections,
                            arrays.scalars};

  nlohmann::ordered_json j;
  j["pair"] = explain::pairRunJson(run, !request.timing);
  j["body"] = explain::pageBodyHtml(shown);
  j["ray_data"] = arrays.scalars;
  j["scene3d"] = explain::sceneViewJson(setup, run.result);
  j["ray_arrays"] = {{"offset", reinterpret_cast<std::uintptr_t>(page.rays.data())},
                     {"pixels", arrays.cases.size()},
                     {"order",
                      "depth after each step, stencil after each step, a_front, "
                      "a_back, b_front, b_back, coverage, case"}};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const explain::KeptPicture& p : page.pictures)
    list.push_back({{"file", p.file},
                    {"width", p.image.width()},
                    {"height", p.image.height()},
                    {"offset", reinterpret_cast<std::uintptr_t>(p.image.bytes().data())}});
  j["pictures"] = list;
  page.json = j.dump();
  return page;
}

}  // namespace recode::wasm
