#pragma once
// What the explain page says, for a student who has not read the paper (HTML fragments).

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "recode/pair/pair.hpp"
#include "recode/raster/state.hpp"

namespace recode::explain {

inline constexpr std::string_view kSilhouettesTitle = "The two blocks and the MOR";
inline constexpr std::string_view kContactTitle = "The contact region";

// A step as the pages name it: `name` the short name the section's heading starts with and
// the ray inspector, the interactive page's exercises and its terms show ("1 SetZ"); `rule`
// what the step does at one pixel, in plain text, the rule a student checks a prediction
// against. Stated here once: the pages' scripts read them from the ray data ("step_words").
struct StepWords {
  std::string_view name;
  std::string_view rule;
};
[[nodiscard]] StepWords stepWords(core::PairStep step);
// What decides the stencil a step leaves at a pixel, besides the stencil before it and whether
// the pixel is in the MOR: the face depths it compares, named as the ray data's arrays
// ("a_front" is A's entry Amin, "a_back" its exit Amax, likewise "b_front", "b_back"), and
// "a_covers", whether A covers the pixel. Empty for a step that leaves the stencil as it found
// it or only reads it. Sent with the names ("step_words"): the exercises show a wrong pass's
// inputs by it.
[[nodiscard]] std::span<const std::string_view> stepOperands(core::PairStep step);
// The heading of a step's section: its name and what it draws.
[[nodiscard]] std::string stepTitle(core::PairStep step);
// Whether the step is the paper's or was added here, with one sentence why (a paragraph).
[[nodiscard]] std::string originText(core::PairStep step);
// The device state a step ran with, read from the device, and the depth it cleared to (a
// paragraph); `clearDepth` < 0: the step clears no depth.
[[nodiscard]] std::string stateText(const raster::RenderState& state, double clearDepth);
// What the step does and why, as paragraphs.
[[nodiscard]] std::string stepText(core::PairStep step);
// What a stencil value means once `step` has run (a legend label).
[[nodiscard]] std::string stencilMeaning(std::uint8_t value, core::PairStep step);

// The first section: the silhouettes, the MOR of mode `mor` and, when the boxes are apart,
// what the box test did. `frame` is the whole frame.
[[nodiscard]] std::string silhouettesText(const core::PairResult& result, core::MorMode mor,
                                          bool boxTest, const raster::PixelRect& frame);
// The nine cases with their conditions, stencil values and pixel counts, and how to read it.
[[nodiscard]] std::string caseTableHtml(const core::PairResult& result);
// The nine cases with their conditions, stencil values and whether they interfere, without
// a run's counts: the definition the interactive page's terms give (rows term-case-0 to -8).
[[nodiscard]] std::string caseDefinitionsHtml();
// The contact region's measures.
[[nodiscard]] std::string contactText(const core::ContactRegion& contact);
// "The blocks collide" or "No collision", with the numbers behind it.
[[nodiscard]] std::string verdictHtml(const core::PairResult& result);

}  // namespace recode::explain
