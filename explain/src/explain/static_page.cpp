#include "explain/static_page.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "explain/explain_page.hpp"
#include "explain/explain_pictures.hpp"
#include "explain/explain_rays.hpp"
#include "explain/explain_recorder.hpp"
#include "explain/explain_sections.hpp"
#include "recode/pair/frame.hpp"
#include "recode/raster/cpu_device.hpp"

namespace recode::explain {

ExplainSummary explainPairInto(const PairSetup& setup, const std::string& morName, bool boxTest,
                               const std::filesystem::path& dir, const std::string& descentHtml) {
  const core::FrameSpec& f = setup.frame;
  if (f.width > kMaxExplainSide || f.height > kMaxExplainSide)
    throw std::invalid_argument("the frame is " + std::to_string(f.width) + "x" +
                                std::to_string(f.height) + "; recode explain draws at most " +
                                std::to_string(kMaxExplainSide) +
                                " pixels a side (use --resolution)");
  // Run the pair, keeping the buffers after every step.
  core::PairRequest request;
  request.frame = f;
  request.mor = core::parseMorMode(morName).value();  // callers pass min, max or full
  request.contact = true;
  request.boxTest = boxTest;
  raster::CpuDevice device(f.width, f.height);
  StepRecorder recorder;
  ExplainSummary summary;
  summary.result = core::collidePair(device, setup.a, setup.b, request, &recorder);
  const core::PairResult& result = summary.result;
  ExplainedRun run = explainRun(setup, result, recorder.snapshots(), request.mor, boxTest, dir,
                                nullptr, descentHtml);
  const std::vector<Section>& sections = run.sections;
  const nlohmann::json rayData = rayDataJson(std::move(run.rays));

  const Page page{setup, morName, result, run.scale, run.view, sections, rayData};
  writeIndexHtml(dir, page);
  writeExplainJson(dir, page);
  for (const Section& s : sections)
    for (const Picture& p : s.pictures) {
      ++summary.pictures;
      if (p.kind == "cases" || (p.kind == "silhouettes" && summary.thumbnail.empty()))
        summary.thumbnail = p.file;
    }
  return summary;
}

}  // namespace recode::explain
