#pragma once
// The explain page's sections in order, each with its text and pictures: what `recode
// explain` writes and what the interactive page (wasm/) shows after every change.

#include <filesystem>
#include <string>
#include <vector>

#include "explain/explain_page.hpp"
#include "explain/explain_pictures.hpp"
#include "explain/explain_rays.hpp"
#include "explain/explain_recorder.hpp"
#include "recode/pair/pair.hpp"

namespace recode::explain {

// The silhouettes, the box descent when `descentHtml` is not empty, one section per recorded
// step and, when the blocks collide, the contact region; their pictures are made by
// `pictures` on the way.
[[nodiscard]] std::vector<Section> buildSections(const core::PairResult& result,
                                                 const std::vector<StepSnapshot>& snapshots,
                                                 core::MorMode mor, bool boxTest,
                                                 PictureWriter& pictures,
                                                 const std::string& descentHtml);

// One run pictured, as both pages show it: the sections and the ray inspector's data, with the
// scale and region of the pictures.
struct ExplainedRun {
  std::vector<Section> sections;
  RayArrays rays;
  int scale = 1;
  raster::PixelRect view;
};

// From a pair run recorded step by step: both blocks' coverage, the sections (their pictures
// written into `dir`, or kept in `kept`: PictureWriter), both blocks' face depths and the ray
// data over the inspector's crop.
[[nodiscard]] ExplainedRun explainRun(const PairSetup& setup, const core::PairResult& result,
                                      const std::vector<StepSnapshot>& snapshots, core::MorMode mor,
                                      bool boxTest, const std::filesystem::path& dir,
                                      std::vector<KeptPicture>* kept,
                                      const std::string& descentHtml);

}  // namespace recode::explain
