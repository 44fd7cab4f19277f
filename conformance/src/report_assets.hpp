#pragma once
// The HTML report's style sheet and script (conformance/page/), embedded into the library at
// build time (cmake/embed_text_files.cmake), so that the page is one file with nothing beside it.

namespace recode::conformance {

// conformance/page/report.css.
extern const char* const kReportCss;
// conformance/page/report.js: paints the error masks.
extern const char* const kReportJs;

}  // namespace recode::conformance
