#pragma once
// The explain page's style sheets and script, written as files in apps/explain/page/ and
// embedded into the program at build time (cmake/embed_text.cmake), so the page needs no file
// beside the program and the files stay readable, lintable CSS and JavaScript.

namespace recode::app::explain {

extern const char* const kPageCss;       // page/page.css: text, figures, legends, tables
extern const char* const kInspectorCss;  // page/inspector.css: the ray inspector's panel
extern const char* const kInspectorJs;   // page/inspector.js: the ray inspector

}  // namespace recode::app::explain
