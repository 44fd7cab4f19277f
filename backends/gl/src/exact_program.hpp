#pragma once
// Compiles and links the exact GL device's shader program from the embedded sources.

#include "gl_functions.hpp"

namespace recode::backends::detail {

// The linked program (vertex + fragment stage over the shared contract functions). Throws
// std::runtime_error with the driver's log when a stage does not compile or link, e.g. on a
// driver without GL_ARB_gpu_shader_int64.
[[nodiscard]] GLuint buildExactProgram(const GlCoreFunctions& gl);

// The linked compute program of the pixel summaries (summary_gl.comp over pixel_summary.glsl,
// integer arithmetic only). Throws std::runtime_error with the driver's log as above.
[[nodiscard]] GLuint buildSummaryProgram(const GlCoreFunctions& gl);

}  // namespace recode::backends::detail
