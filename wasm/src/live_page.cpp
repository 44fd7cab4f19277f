#include "live_page.hpp"

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

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
  // One block of numbers, the arrays one after the other in the order "ray_arrays.order"
  // names them (per_step: one array per step): the page makes typed arrays of it by those
  // names instead of reading hundreds of thousands of numbers as JSON.
  nlohmann::ordered_json order = nlohmann::ordered_json::array();
  explain::forEachRayArray(arrays, [&](std::string_view name, const auto& values) {
    using Values = std::decay_t<decltype(values)>;
    constexpr bool perStep = std::is_same_v<Values, std::vector<std::vector<std::uint32_t>>>;
    order.push_back({{"name", name}, {"per_step", perStep}});
    if constexpr (perStep) {
      for (const auto& step : values)
        page.rays.insert(page.rays.end(), step.begin(), step.end());
    } else {
      page.rays.insert(page.rays.end(), values.begin(), values.end());
    }
  });
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
                     {"order", order}};
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
