#pragma once
// `recode explain --gallery`: one small built-in pair per case 1-8, and a pair that is apart,
// each explained on a page of its own, with an index that links them.

#include <cstddef>
#include <filesystem>

#include "recode/pair/frame.hpp"

namespace recode::explain {

// Writes DIR/<pair>/ (index.html, explain.json, pictures) for every gallery pair and
// DIR/index.html linking them; `overrides` replaces the pairs' own 48 x 48 frame. Returns
// the number of pair pages. DIR must exist.
std::size_t writeGallery(const std::filesystem::path& dir, const core::FrameOverrides& overrides);

}  // namespace recode::explain
