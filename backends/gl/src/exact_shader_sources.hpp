#pragma once
// The exact devices' GLSL, embedded at build time from backends/exact/shaders and
// backends/gl/shaders (cmake/embed_text.cmake).
// Each is a body without a #version line: the device prepends the header its API needs.

namespace recode::backends::detail {

extern const char* const kExactContractGlsl;  // shaders/exact_contract.glsl
extern const char* const kExactGlVertex;      // shaders/exact_gl.vert
extern const char* const kExactGlFragment;    // shaders/exact_gl.frag
extern const char* const kPixelSummaryGlsl;   // backends/exact/shaders/pixel_summary.glsl
extern const char* const kSummaryGlCompute;   // shaders/summary_gl.comp

}  // namespace recode::backends::detail
