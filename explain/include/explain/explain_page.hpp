#pragma once
// Writes the explain page: index.html (sections of text and pictures) and explain.json.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "explain/explain_pictures.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair.hpp"

namespace recode::explain {

struct Section {
  std::string id;
  std::string step;   // the PairStep's name, or "" for sections that are not a step
  std::string title;  // HTML
  std::string text;   // HTML paragraphs
  std::vector<Picture> pictures;
};

// Everything the page shows about one run.
struct Page {
  const PairSetup& setup;
  std::string morMode;  // as given: min, max or full
  const core::PairResult& result;
  int scale;               // picture pixels per framebuffer pixel in the pictures of `view`
  raster::PixelRect view;  // the part of the frame the pictures show (not the close-ups)
  const std::vector<Section>& sections;
  const nlohmann::json& rayData;  // the inspector's data (explain_rays.hpp)
};

// The page's body without the ray inspector: the run, how RECODE works, every section with its
// pictures (<img> by file name) and legends, and the verdict.
[[nodiscard]] std::string pageBodyHtml(const Page& page);

// dir/index.html: the run, how RECODE works, every section with its pictures and legends,
// and the verdict. Throws std::runtime_error naming the file on failure.
void writeIndexHtml(const std::filesystem::path& dir, const Page& page);

// dir/explain.json: the run, the result, the palettes and every section's pictures. Throws
// std::runtime_error naming the file on failure.
void writeExplainJson(const std::filesystem::path& dir, const Page& page);

}  // namespace recode::explain
