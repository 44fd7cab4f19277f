// The ray inspector of the explain page: plain HTML, CSS, SVG and JavaScript, no network. Its
// style and script are page/inspector.css and page/inspector.js, embedded at build time.
#include "explain/explain_inspector.hpp"

#include <string>

#include "explain/page_assets.hpp"

namespace recode::explain {

std::string scriptSafe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/')
      out += "\\";
  }
  return out;
}

std::string_view inspectorStyle() {
  return kInspectorCss;
}

std::string inspectorPanelHtml() {
  return "<aside id=\"inspector\" aria-live=\"polite\"><div id=\"steps\"><label "
         "for=\"step-slider\">"
         "step</label><input type=\"range\" id=\"step-slider\" min=\"0\" max=\"0\" step=\"1\" "
         "value=\"0\"><span id=\"step-name\"></span></div><div id=\"steps-help\">&larr;/&rarr; "
         "or the slider: step; click a picture: pin a pixel (Esc: follow the pointer again)</div>"
         "<div id=\"inspector-body\"><h3 id=\"inspector-title\">Ray inspector</h3><p>Move the "
         "pointer over any picture, or click it, to follow that pixel's ray through every "
         "step.</p></div></aside>\n";
}

std::string inspectorHtml(const nlohmann::json& rayData) {
  std::string h = inspectorPanelHtml() + "<script type=\"application/json\" id=\"ray-data\">";
  h += scriptSafe(rayData.dump());
  h += "</script>\n<script>";
  h += kCommonJs;
  h += "</script>\n<script>";
  h += kInspectorJs;
  h += "</script>\n";
  return h;
}

}  // namespace recode::explain
