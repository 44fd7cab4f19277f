// `recode explain --gallery`: small built-in pairs chosen so that each shows one case.
#include "explain/explain_gallery.hpp"

#include <array>
#include <sstream>
#include <string>
#include <string_view>

#include "explain/explain_format.hpp"
#include "explain/explain_palette.hpp"
#include "explain/static_page.hpp"
#include "output/atomic_file.hpp"
#include "pair/pair_setup.hpp"
#include "recode/pair/pair_cases.hpp"
#include "recode/scene/scene.hpp"

namespace recode::explain {

namespace {

namespace fs = std::filesystem;

// Boxes seen along z: the viewer is on the +z side, so a larger z is nearer. A is 2 units
// deep (z from -1 to 1) unless said otherwise; B is placed in depth to produce the case on
// every pixel both boxes cover.
struct GalleryPair {
  std::string_view id;
  int featured;  // the case the pair is there to show; -1: none (apart)
  std::string_view title;
  std::string_view why;  // HTML
  std::string_view mor;
  bool boxTest;
  std::string_view objects;  // the scene's "objects" array
};

constexpr std::array<GalleryPair, 9> kPairs = {{
    {"case-1", 1, "A only",
     "A is wider than B: with <code>--mor max</code> the MOR takes in "
     "the ring of A around B, where only A is on the ray (in the middle B lies inside A: case 5).",
     "max", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [3, 3, 2]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0, 0, 0]}])"},
    {"case-2", 2, "B behind A",
     "B lies wholly behind A (smaller z, farther from the viewer). "
     "The box test would stop before any pass, since the depth ranges do not meet; "
     "<code>--no-box-test</code> runs the passes to show how the stencil records it.",
     "min", false,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 1]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0.3, 0.2, -2]}])"},
    {"case-3", 3, "B's near end inside A, its far end behind",
     "B reaches from z = 0, inside A, to z = -2, behind A's far side at z = -1.", "min", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 2]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 2]}, "position": [0.3, 0.2, -1]}])"},
    {"case-4", 4, "B spans A", "B reaches from z = 2 to z = -2, through all of A (z from 1 to -1).",
     "min", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 2]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 4]}, "position": [0.3, 0.2, 0]}])"},
    {"case-5", 5, "A spans B", "B (z from 0.5 to -0.5) lies inside A's depth (z from 1 to -1).",
     "min", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 2]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0.3, 0.2, 0]}])"},
    {"case-6", 6, "B's far end inside A, its near end in front",
     "B reaches from z = 2, in front of A, to z = 0, inside A.", "min", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 2]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 2]}, "position": [0.3, 0.2, 1]}])"},
    {"case-7", 7, "B in front of A",
     "B lies wholly in front of A (larger z, nearer the viewer). "
     "As for case 2, the box test would stop before any pass; <code>--no-box-test</code> runs "
     "them.",
     "min", false,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 1]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0.3, 0.2, 2]}])"},
    {"case-8", 8, "B only",
     "B is wider than A: with <code>--mor max</code> the MOR takes in the "
     "ring of B around A, where only B is on the ray (in the middle B spans A: case 4).",
     "max", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [3, 3, 2]}, "position": [0, 0, 0]}])"},
    {"apart", -1, "Apart: the box test",
     "The case-2 pair with the box test on: the two "
     "boxes' depth ranges do not meet, so RECODE decides &ldquo;no collision&rdquo; before "
     "drawing anything, and the page stops after the first picture.",
     "min", true,
     R"([{"name": "A", "shape": {"type": "box", "size": [2, 2, 1]}, "position": [0, 0, 0]},
         {"name": "B", "shape": {"type": "box", "size": [1, 1, 1]}, "position": [0.3, 0.2, -2]}])"},
}};

constexpr int kGallerySide = 48;

PairSetup gallerySetup(const GalleryPair& pair, const core::FrameOverrides& overrides) {
  const std::string json = R"({"view": {"axis": "z", "resolution": [)" +
                           std::to_string(kGallerySide) + ", " + std::to_string(kGallerySide) +
                           R"(]}, "objects": )" + std::string(pair.objects) + "}";
  const core::Scene scene =
      core::parseScene(json, "gallery pair " + std::string(pair.id), fs::current_path());
  PairSetup setup = pairSetupFromScene(scene, overrides);
  setup.source = "the gallery pair " + std::string(pair.id);
  return setup;
}

}  // namespace

std::size_t writeGallery(const fs::path& dir, const core::FrameOverrides& overrides) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>RECODE: a "
       "gallery of the nine cases</title><link rel=\"icon\" href=\"data:,\"><style>\n"
       "body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;"
       "line-height:1.45;color:#222}table{border-collapse:collapse}td,th{border:1px solid "
       "#bbb;padding:.3em .6em;vertical-align:top;text-align:left}img{image-rendering:"
       "pixelated;width:160px;border:1px solid #888}.sw{display:inline-block;width:1em;"
       "height:1em;border:1px solid #555;vertical-align:middle;margin-right:.3em}\n"
       "</style></head><body>\n<h1>A gallery of the nine cases</h1>\n<p>One small pair of "
       "boxes per case, seen along z (the viewer on the +z side, so a larger z is nearer). "
       "Each page runs every pass on its pair; open it and point at a pixel to follow its "
       "ray. Case 0 (no block on the ray) is around every pair.</p>\n<table><tr><th>case"
       "</th><th>the pair</th><th>pixels of the case</th><th>verdict</th><th>case map"
       "</th></tr>\n";
  std::size_t pages = 0;
  for (const GalleryPair& pair : kPairs) {
    const PairSetup setup = gallerySetup(pair, overrides);
    const fs::path sub = dir / std::string(pair.id);
    output::CreatedDirectory created(sub, "--out " + sub.string());
    const ExplainSummary s = explainPairInto(setup, std::string(pair.mor), pair.boxTest, sub);
    created.keep();
    ++pages;
    const core::PairResult& r = s.result;
    h << "<tr id=\"" << pair.id << "\"><td>";
    if (pair.featured >= 0)
      h << swatch(kCasePalette[static_cast<std::size_t>(pair.featured)]) << "<b>" << pair.featured
        << "</b>";
    else
      h << "&ndash;";
    h << "</td><td><a href=\"" << pair.id << "/index.html\"><b>" << pair.title << "</b></a><br>"
      << pair.why << "<br><small>MOR <code>" << pair.mor << "</code>"
      << (pair.boxTest ? "" : ", <code>--no-box-test</code>") << "</small></td><td>";
    if (pair.featured >= 0)
      h << r.caseCounts[static_cast<std::size_t>(pair.featured)] << " of " << r.mor.area()
        << " MOR pixels";
    else
      h << (r.boxesOverlap ? "boxes overlap" : "boxes apart: nothing drawn");
    h << "</td><td>" << (r.collide ? "collide" : "no collision") << "</td><td><a href=\"" << pair.id
      << "/index.html\"><img src=\"" << pair.id << '/' << s.thumbnail << "\" alt=\"" << pair.id
      << " case map\"></a></td></tr>\n";
  }
  h << "</table>\n</body></html>\n";
  output::writeFileAtomically(dir / "index.html", h.str());
  return pages;
}

}  // namespace recode::explain
