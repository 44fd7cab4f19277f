#pragma once
// The ray inspector of the explain page: its style, its panel and the script that draws, for
// the pixel under the pointer, the ray with both blocks' intervals and every pass's values.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace recode::explain {

// CSS for the inspector panel, the step slider, the picture markers and printing.
[[nodiscard]] std::string_view inspectorStyle();

// The panel, the step slider, the ray data (inline JSON: the page works from file:// with
// nothing beside it but its pictures) and the script. `rayData` is rayDataJson()'s object.
[[nodiscard]] std::string inspectorHtml(const nlohmann::json& rayData);

// The panel and the step slider alone, for a page that hands the script its ray data itself
// (window.recodeInspector.attach, the interactive page).
[[nodiscard]] std::string inspectorPanelHtml();

// JSON made safe inside <script>: no "</" that could close the element early.
[[nodiscard]] std::string scriptSafe(const std::string& json);

}  // namespace recode::explain
