#include "explain/interactive_page.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

#include "explain/explain_inspector.hpp"
#include "explain/explain_text.hpp"
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

// Puts `with` where the skeleton has `marker` (once, or the skeleton is broken).
void fill(std::string& page, std::string_view marker, std::string_view with) {
  const std::size_t at = page.find(marker);
  if (at == std::string::npos || page.find(marker, at + 1) != std::string::npos)
    throw std::runtime_error("page/interactive.html must hold " + std::string(marker) + " once");
  page.replace(at, marker.size(), with);
}

}  // namespace

void writeInteractivePage(const std::filesystem::path& dir, std::string_view wasmModuleJs) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<title>RECODE, live</title><link rel=\"icon\" href=\"data:,\"><style>\n";
  h += kPageCss;
  h += inspectorStyle();
  h += kInteractiveCss;
  h += "</style></head><body>\n";
  // The body's skeleton (page/interactive.html) with the ray inspector's panel after the
  // pictures (docked there on a narrow window) and the case table in its terms.
  std::string body = kInteractiveHtml;
  fill(body, "<!--inspector-->", inspectorPanelHtml());
  fill(body, "<!--cases-->", caseDefinitionsHtml());
  h += body;
  h += "<script>";
  h += scriptText(kCommonJs, "page/common.js");
  h += "</script>\n<script>";
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
