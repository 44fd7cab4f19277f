#pragma once
// The explain page's sections in order, each with its text and pictures: what `recode
// explain` writes and what the interactive page (wasm/) shows after every change.

#include <string>
#include <vector>

#include "explain/explain_page.hpp"
#include "explain/explain_pictures.hpp"
#include "explain/explain_recorder.hpp"
#include "recode/pair/pair.hpp"

namespace recode::app::explain {

// The silhouettes, the box descent when `descentHtml` is not empty, one section per recorded
// step and, when the blocks collide, the contact region; their pictures are made by
// `pictures` on the way.
[[nodiscard]] std::vector<Section> buildSections(const core::PairResult& result,
                                                 const std::vector<StepSnapshot>& snapshots,
                                                 core::MorMode mor, bool boxTest,
                                                 PictureWriter& pictures,
                                                 const std::string& descentHtml);

}  // namespace recode::app::explain
