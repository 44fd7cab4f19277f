#pragma once
// The explain pages' style sheets and scripts, written as files in explain/page/ and embedded
// into the library at build time (cmake/embed_text_files.cmake), so the pages need no file
// beside the program and the files stay readable, lintable CSS and JavaScript.

namespace recode::explain {

extern const char* const kPageCss;          // page/page.css: text, figures, legends, tables
extern const char* const kInspectorCss;     // page/inspector.css: the ray inspector's panel
extern const char* const kCommonJs;         // page/common.js: what the scripts share
extern const char* const kInspectorJs;      // page/inspector.js: the ray inspector
extern const char* const kInteractiveCss;   // page/interactive.css: the interactive page
extern const char* const kInteractiveJs;    // page/interactive.js: the interactive page
extern const char* const kScene3dJs;        // page/scene3d.js: its 3-D view (WebGL2)
extern const char* const kPredictJs;        // page/predict.js: its exercises
extern const char* const kInteractiveHtml;  // page/interactive.html: its body's skeleton

}  // namespace recode::explain
