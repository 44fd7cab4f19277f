#include "explain/interactive_page.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

#include "explain/explain_inspector.hpp"
#include "explain/page_assets.hpp"
#include "output/atomic_file.hpp"

namespace recode::app::explain {

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
    "and forth, so the cases can be watched appearing as the blocks start to touch. Every "
    "section below is the one <code>recode explain</code> writes, for this pose; the ray "
    "inspector follows any pixel through every step. <b>Export</b> saves the scene as a scene "
    "file: <code>recode pair scene.json --mor MOR</code> gives this page's answer.</p>\n";

constexpr const char* kSummary =
    "<div id=\"live-summary\"><p id=\"live-status\">loading the WebAssembly module&hellip;</p>"
    "<p>Verdict: <span id=\"live-verdict\" class=\"verdict\"></span> &mdash; "
    "<span id=\"live-interfering\"></span></p><table id=\"case-counts\"></table>"
    "<p>Last update: <span id=\"update-ms\"></span></p><p id=\"live-error\" hidden></p>"
    "<p><button id=\"export\">Export the scene</button> (scene.json, and the OBJ file of a "
    "block made from one)</p><textarea id=\"scene-text\" readonly aria-label=\"the scene "
    "file\"></textarea></div>\n";

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
  h += "<div id=\"live-controls\"></div>\n";
  h += kSummary;
  h += "<div id=\"live-result\"></div>\n";
  h += inspectorPanelHtml();
  h += "<script>";
  h += scriptText(kInspectorJs, "page/inspector.js");
  h += "</script>\n<script>";
  h += scriptText(wasmModuleJs, "the WebAssembly module");
  h += "</script>\n<script>";
  h += scriptText(kInteractiveJs, "page/interactive.js");
  h += "</script>\n</body></html>\n";
  writeFileAtomically(dir / "index.html", h);
}

}  // namespace recode::app::explain
