// Writes the explain page: index.html (sections of text and pictures) and explain.json.
#include "explain/explain_page.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "explain/explain_format.hpp"
#include "explain/explain_inspector.hpp"
#include "explain/explain_palette.hpp"
#include "explain/explain_text.hpp"
#include "explain/page_assets.hpp"
#include "output/atomic_file.hpp"

namespace recode::explain {

namespace {

namespace fs = std::filesystem;
using raster::PixelRect;

void writeText(const fs::path& path, const std::string& text) {
  output::writeFileAtomically(path, text);
}

nlohmann::json colourJson(Rgb c) {
  return nlohmann::json::array({c.r, c.g, c.b});
}

// The page's head up to its style sheet (page/page.css, embedded at build time).
constexpr const char* kPageHead =
    "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
    "<title>RECODE step by step</title><link rel=\"icon\" href=\"data:,\"><style>\n";

void writeHowItWorks(std::ostream& h, int scale) {
  h << "<h2>How RECODE works, and how to read the pictures</h2>\n"
       "<p>RECODE (REndered COllision DEtection, Baciu, Wong and Sun 1999) decides whether "
       "two convex blocks A and B touch by <i>drawing</i> them, as a graphics card would, "
       "instead of intersecting their triangles in 3-D. A graphics card keeps two numbers "
       "for every pixel besides its colour: the <b>depth</b> (how far along the view "
       "direction the drawn surface is, 0 nearest to the viewer, 1 farthest, stored as a "
       "24-bit integer) and the <b>stencil</b> (an 8-bit counter). When a triangle is "
       "drawn, each pixel it covers produces a <i>fragment</i> with its own depth. The "
       "<b>depth test</b> compares it with the stored depth (e.g. <code>LEQUAL</code>: pass "
       "if the fragment is at or in front of what is stored) and, if depth writes are on, "
       "a passing fragment stores its depth. The <b>stencil test</b> compares the stored "
       "stencil with a reference value, and the <b>stencil operations</b> say what to do "
       "with the stencil when the stencil test fails, when the depth test fails, or when "
       "both pass (keep, replace, increment, invert a bit...).</p>\n"
       "<p>RECODE chooses these tests so that after a few passes each pixel's stencil "
       "tells how the two blocks' depth intervals along that pixel's ray are arranged: one "
       "of nine <b>cases</b>, numbered 0 to 8 (no block on the ray, A only, B only, B behind "
       "A, B in front of A, and four ways of overlapping; the read-back's section tables "
       "them). A pixel in case 3, 4, 5 or 6 is an <b>interfering pixel</b>: its two "
       "intervals share at least one depth, so its ray passes through a point inside both "
       "blocks, and the blocks collide if and only if some pixel interferes. Reading the "
       "stencil back then gives the verdict and the contact region. Here every "
       "pass runs on the reference CPU depth/stencil machine, exactly as a GPU back end "
       "would run it.</p>\n"
       "<p id=\"device-state-terms\">Each step's <b>Device state</b> line lists what it ran "
       "with. The <b>scissor</b> is the rectangle outside which nothing is drawn or cleared. "
       "The stencil test compares its reference value <b>ref</b> with the stored stencil, "
       "both first ANDed with the value <b>mask</b> (the bits the test reads): "
       "<code>LEQUAL</code> passes when ref &le; stored, so ref 1 with mask 0x03 is the test "
       "1 &le; count on bits 0-1; <code>ALWAYS</code> passes every fragment, "
       "<code>NEVER</code> none. The ops sfail / dpfail / dppass are what a fragment does to "
       "the stencil when the stencil test fails, when the depth test fails, and when both "
       "pass (<code>REPLACE</code> writes ref). The <b>write mask</b> is the bits an op may "
       "change. <b>Culling</b> names the faces not drawn at all: <code>back</code> skips the "
       "triangles facing away from the viewer, <code>front</code> those facing it, "
       "<code>none</code> draws both.</p>\n"
       "<p>Pictures: each framebuffer pixel is shown as a "
    << scale << " &times; " << scale
    << " block (close-ups magnify more), the top of the picture is the top of the frame. "
       "Nothing outside the MOR is ever drawn, so the pictures show the MOR with a margin "
       "(the first picture shows where that lies in the whole frame); the line under each "
       "picture gives its edges in pixels and world units, the viewer's side and a scale "
       "bar. The cyan frame is the MOR, the green frame where the close-up is; dimmed, "
       "hatched pixels are outside the rectangle a step works in (the step does not touch "
       "them). The &ldquo;changed&rdquo; pictures colour each stencil change (old value "
       "&rarr; new value) on its own. Depth pictures show near as bright and far "
       "as dark, stretched over the depths drawn in the step. <b>Point at any pixel of any "
       "picture</b> (click to pin it) to follow its ray through every step in the <a "
       "href=\"#inspector\">ray inspector</a> (at the bottom right of a window 1100 pixels "
       "wide or more, below the page's pictures on a narrower one); the slider or the "
       "&larr; and &rarr; keys move through the steps. Notation: A<sub>min</sub> and "
       "A<sub>max</sub> are the depths where a pixel's ray enters and leaves A, likewise "
       "B<sub>min</sub>, B<sub>max</sub>.</p>\n";
}

// The world axes the image plane's u and v are (docs/algorithm.md section 2), and the axis
// the viewer looks along.
struct PlaneAxes {
  const char* u;
  const char* v;
  const char* depth;
};
PlaneAxes planeAxes(core::ViewAxis axis) {
  switch (axis) {
    case core::ViewAxis::X:
      return {"y", "z", "x"};
    case core::ViewAxis::Y:
      return {"z", "x", "y"};
    case core::ViewAxis::Z:
      break;
  }
  return {"x", "y", "z"};
}

// A round length (1, 2 or 5 times a power of ten) of world units that spans 40 to 120
// picture pixels at `pixelsPerUnit`.
double scaleBarLength(double pixelsPerUnit) {
  double length = std::pow(10.0, std::floor(std::log10(80.0 / pixelsPerUnit)));
  for (double step : {1.0, 2.0, 5.0, 10.0})
    if (step * length * pixelsPerUnit >= 40.0)
      return step * length;
  return 10.0 * length;
}

// Under each picture: what its edges are in pixels and world units, where the viewer is, and
// a scale bar.
void writeAxes(std::ostream& h, const Picture& p, const core::FrameSpec& f) {
  const PlaneAxes a = planeAxes(f.axis);
  const core::ViewWindow& w = f.window;
  const double pw = (w.umax - w.umin) / f.width, ph = (w.vmax - w.vmin) / f.height;
  const PixelRect& r = p.region;
  h << "<div class=\"axes\">x &rarr; pixels " << r.x0 << "&ndash;" << r.x1 - 1 << " (world " << a.u
    << " " << formatNumber(w.umin + r.x0 * pw) << " to " << formatNumber(w.umin + r.x1 * pw)
    << "); y &uarr; rows " << r.y0 << "&ndash;" << r.y1 - 1 << " (world " << a.v << " "
    << formatNumber(w.vmin + r.y0 * ph) << " to " << formatNumber(w.vmin + r.y1 * ph)
    << "). Viewer on the +" << a.depth << " side, looking along &minus;" << a.depth
    << " into the picture. ";
  const double pixelsPerUnit = p.scale / pw;
  if (std::isfinite(pixelsPerUnit) && pixelsPerUnit > 0) {
    const double length = scaleBarLength(pixelsPerUnit);
    h << "<span class=\"scalebar\" style=\"width:" << std::lround(length * pixelsPerUnit)
      << "px\"></span> " << formatNumber(length) << " world units";
  }
  h << "</div>";
}

void writeFigure(std::ostream& h, const Picture& p, const core::FrameSpec& frame) {
  const PixelRect& r = p.region;
  h << "<figure><img src=\"" << p.file << "\" width=\"" << p.width << "\" height=\"" << p.height
    << "\" data-region=\"" << r.x0 << ',' << r.y0 << ',' << r.x1 << ',' << r.y1 << "\" alt=\""
    << p.kind << (p.zoom ? " close-up" : "") << "\">";
  writeAxes(h, p, frame);
  h << "<figcaption>" << p.caption << "<ul class=\"legend\">";
  if (p.depthLegend) {
    const bool clearedToOne = p.depthClear == 1.0;
    h << "<li>near (" << formatNumber(p.depthNear) << ") <span class=\"grad\"></span> far ("
      << formatNumber(p.depthFar) << "), stretched over the depths drawn here</li><li>"
      << swatch(clearedToOne ? kDepthOne : kDepthZero) << "exactly " << (clearedToOne ? "1" : "0")
      << ": this step cleared depth to " << (clearedToOne ? "1" : "0")
      << " and drew nothing here</li><li>" << swatch(clearedToOne ? kDepthZero : kDepthOne)
      << "exactly " << (clearedToOne ? "0" : "1") << ": left by an earlier step</li><li>"
      << swatch(kHatch) << "hatched, dimmed: outside the rectangle this step draws in</li>";
  }
  for (const LegendEntry& e : p.legend) {
    h << "<li>" << swatch(e.colour) << e.label;
    if (e.pixels >= 0)
      h << " &mdash; " << e.pixels << " px";
    h << "</li>";
  }
  h << "</ul></figcaption></figure>\n";
}

nlohmann::json rectJson(const PixelRect& r) {
  return nlohmann::json::array({r.x0, r.y0, r.x1, r.y1});
}

nlohmann::json contactJson(const core::ContactRegion& contact) {
  nlohmann::json j;
  j["pixels"] = contact.pixels;
  j["area"] = contact.area;
  j["max_depth"] = contact.maxDepth;
  if (!contact.box.isEmpty()) {
    const auto& b = contact.box;
    j["box"] = {{b.min.x(), b.min.y(), b.min.z()}, {b.max.x(), b.max.y(), b.max.z()}};
  }
  return j;
}

// The colours the pictures use, so that a reader of explain.json can decode them.
nlohmann::json palettesJson() {
  nlohmann::json palettes;
  nlohmann::json cases = nlohmann::json::object();
  for (int c = 0; c < core::kCaseCount; ++c)
    cases[std::to_string(c)] = colourJson(kCasePalette[static_cast<std::size_t>(c)]);
  palettes["cases"] = cases;
  nlohmann::json stencil = nlohmann::json::object();
  for (std::size_t v = 0; v < kStencilPalette.size(); ++v)
    stencil[std::to_string(v)] = colourJson(kStencilPalette[v]);
  palettes["stencil"] = stencil;
  palettes["silhouettes"] = {{"a", colourJson(kColourA)},
                             {"b", colourJson(kColourB)},
                             {"both", colourJson(kColourBoth)},
                             {"neither", colourJson(kEmpty)}};
  palettes["interfering"] = colourJson(kInterfering);
  return palettes;
}

// "sections" names each section's files; "pictures" describes every file once.
void addSectionsJson(nlohmann::json& j, const std::vector<Section>& sectionList) {
  nlohmann::json sections = nlohmann::json::array();
  nlohmann::json pictures = nlohmann::json::array();
  for (const Section& s : sectionList) {
    nlohmann::json files = nlohmann::json::array();
    for (const Picture& p : s.pictures) {
      files.push_back(p.file);
      pictures.push_back({{"file", p.file},
                          {"kind", p.kind},
                          {"section", s.id},
                          {"zoom", p.zoom},
                          {"region", rectJson(p.region)},
                          {"scale", p.scale},
                          {"width", p.width},
                          {"height", p.height}});
    }
    sections.push_back({{"id", s.id}, {"step", s.step}, {"files", files}});
  }
  j["sections"] = sections;
  j["pictures"] = pictures;
}

}  // namespace

std::string pageBodyHtml(const Page& page) {
  const core::FrameSpec& f = page.setup.frame;
  const std::string source = escapeHtml(page.setup.source);
  std::ostringstream h;
  h << "<h1>RECODE step by step</h1>\n<p>Block A: <b>" << escapeHtml(page.setup.nameA)
    << "</b>, block B: <b>" << escapeHtml(page.setup.nameB) << "</b>, from " << source << ". View "
    << "along the " << core::toString(f.axis) << " axis, " << f.width << " &times; " << f.height
    << " pixels, MOR mode <code>" << escapeHtml(page.morMode) << "</code>.</p>\n"
    << verdictHtml(page.result) << '\n';
  writeHowItWorks(h, page.scale);
  for (const Section& s : page.sections) {
    h << "<section id=\"" << s.id << "\"><h2>" << s.title << "</h2>\n" << s.text << '\n';
    for (const Picture& p : s.pictures)
      writeFigure(h, p, f);
    h << "</section>\n";
  }
  h << "<section id=\"verdict\"><h2>Verdict</h2>" << verdictHtml(page.result) << "</section>\n";
  return h.str();
}

void writeIndexHtml(const fs::path& dir, const Page& page) {
  std::ostringstream h;
  h << kPageHead << kPageCss << inspectorStyle() << "</style></head><body>\n"
    << pageBodyHtml(page) << inspectorHtml(page.rayData) << "</body></html>\n";
  writeText(dir / "index.html", h.str());
}

void writeExplainJson(const fs::path& dir, const Page& page) {
  nlohmann::json j;
  const core::FrameSpec& f = page.setup.frame;
  const core::PairResult& result = page.result;
  j["source"] = page.setup.source;
  j["objects"] = {page.setup.nameA, page.setup.nameB};
  j["axis"] = core::toString(f.axis);
  j["width"] = f.width;
  j["height"] = f.height;
  j["scale"] = page.scale;
  j["view"] = rectJson(page.view);
  j["mor_mode"] = page.morMode;
  j["collide"] = result.collide;
  j["boxes_overlap"] = result.boxesOverlap;
  j["mor"] = rectJson(result.mor);
  j["contact_rect"] = rectJson(result.contactRect);
  nlohmann::json counts = nlohmann::json::object();
  for (int c = 0; c < core::kCaseCount; ++c)
    counts[std::to_string(c)] = result.caseCounts[static_cast<std::size_t>(c)];
  j["case_counts"] = counts;
  j["interfering_pixels"] = result.interferingPixels;
  j["contact"] = contactJson(result.contact);
  j["palettes"] = palettesJson();
  addSectionsJson(j, page.sections);
  writeText(dir / "explain.json", j.dump(2) + "\n");
}

}  // namespace recode::explain
