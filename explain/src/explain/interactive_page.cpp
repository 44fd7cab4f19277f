#include "explain/interactive_page.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

#include "explain/explain_inspector.hpp"
#include "explain/page_assets.hpp"
#include "output/atomic_file.hpp"

namespace recode::explain {

namespace {

// A script's text inside <script>...</script>: it must not close the element itself.
std::string_view scriptText(std::string_view text, const char* what) {
  if (text.find("</script") != std::string_view::npos)
    throw std::runtime_error(std::string(what) + " contains \"</script\" and cannot be inlined");
  return text;
}

constexpr const char* kIntro =
    "<h1>RECODE, live: move the blocks, watch every pass</h1>\n"
    "<p>Two convex blocks A and B, drawn by the reference implementation itself (compiled to "
    "WebAssembly) every time anything changes. Choose each block's shape and size, type a "
    "position or a rotation, or drag any picture below to move a block (shift-drag turns it "
    "about the view axis). The slider moves B through A along an axis; Play sweeps it back "
    "and forth, so the cases can be watched appearing as the blocks start to touch. The 3-D "
    "view shows the blocks as the reference's triangles, the view axis, the frame's window, the "
    "MOR and the ray of the inspected pixel (drag it to turn it). Every section below is the one "
    "<code>recode explain</code> writes, for this pose; the ray inspector follows any pixel "
    "through every step. <b>Predict</b> opens exercises that hide the buffers and check your "
    "reading of every pass. <b>Export</b> saves the scene as a scene file: the command under it "
    "gives this page's answer.</p>\n";

// The controls beside the 3-D view (page/scene3d.js): the canvas's drawing buffer is its CSS
// size, so a pixel of the view is a pixel on the screen.
constexpr const char* kTop =
    "<div id=\"live-top\"><div id=\"live-controls\"></div><figure id=\"view3d-panel\">"
    "<canvas id=\"view3d\" width=\"400\" height=\"400\" aria-label=\"the two blocks in 3-D, "
    "with the view axis, the window, the MOR and the inspected pixel's ray\"></canvas>"
    "<figcaption>The blocks in 3-D: drag to turn, wheel to zoom, double-click to look along the "
    "view axis again (the pictures' view). The ray of the inspected pixel (yellow) is marked "
    "where it enters and leaves each block, at the depths the ray inspector shows."
    "</figcaption><div id=\"view3d-options\"></div><p id=\"view3d-note\"></p></figure></div>\n";

constexpr const char* kSummary =
    "<div id=\"live-summary\"><p id=\"live-status\">loading the WebAssembly module&hellip;</p>"
    "<p>Verdict: <span id=\"live-verdict\" class=\"verdict\"></span> &mdash; "
    "<span id=\"live-interfering\"></span></p><table id=\"case-counts\"></table>"
    "<p>Last update: <span id=\"update-ms\"></span></p><p id=\"live-error\" hidden></p>"
    "<p><button id=\"export\">Export the scene</button> (scene.json, and the OBJ file of a "
    "block made from one); then <code id=\"pair-command\"></code> gives this page's answer.</p>"
    "<textarea id=\"scene-text\" readonly aria-label=\"the scene file\"></textarea></div>\n";

}  // namespace

void writeInteractivePage(const std::filesystem::path& dir, std::string_view wasmModuleJs) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<title>RECODE, live</title><link rel=\"icon\" href=\"data:,\"><style>\n";
  h += kPageCss;
  h += inspectorStyle();
  h += kInteractiveCss;
  h += "</style></head><body>\n";
  h += kIntro;
  h += kTop;
  h += kSummary;
  h += "<section id=\"predict\" aria-live=\"polite\"></section>\n";
  h += "<div id=\"live-result\"></div>\n";
  h += inspectorPanelHtml();
  h += "<script>";
  h += scriptText(kInspectorJs, "page/inspector.js");
  h += "</script>\n<script>";
  h += scriptText(wasmModuleJs, "the WebAssembly module");
  h += "</script>\n<script>";
  h += scriptText(kScene3dJs, "page/scene3d.js");
  h += "</script>\n<script>";
  h += scriptText(kInteractiveJs, "page/interactive.js");
  h += "</script>\n<script>";
  h += scriptText(kPredictJs, "page/predict.js");
  h += "</script>\n</body></html>\n";
  output::writeFileAtomically(dir / "index.html", h);
}

}  // namespace recode::explain
