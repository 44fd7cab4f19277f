#include "exact_program.hpp"

#include <initializer_list>
#include <stdexcept>
#include <string>

#include "exact_shader_sources.hpp"

namespace recode::backends::detail {

namespace {

// GLSL 4.50 has doubles; 64-bit integers need the extension (core only from GLSL 4.60 with
// ARB_gpu_shader_int64 still optional).
constexpr const char* kHeader =
    "#version 450 core\n"
    "#extension GL_ARB_gpu_shader_int64 : require\n";

// Compiles `parts` (their first the version line) as one stage.
GLuint compileParts(const GlCoreFunctions& gl, GLenum stage,
                    std::initializer_list<const char*> parts, const char* what) {
  const GLuint shader = gl.CreateShader(stage);
  gl.ShaderSource(shader, static_cast<GLsizei>(parts.size()), parts.begin(), nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    gl.DeleteShader(shader);
    throw std::runtime_error(std::string("GL exact device: the ") + what +
                             " shader does not compile: " + log);
  }
  return shader;
}

GLuint compileStage(const GlCoreFunctions& gl, GLenum stage, const char* body, const char* what) {
  return compileParts(gl, stage, {kHeader, kExactContractGlsl, body}, what);
}

// Links `shaders` (deleted here) into a program.
GLuint linkProgram(const GlCoreFunctions& gl, std::initializer_list<GLuint> shaders) {
  const GLuint program = gl.CreateProgram();
  for (const GLuint shader : shaders)
    gl.AttachShader(program, shader);
  gl.LinkProgram(program);
  for (const GLuint shader : shaders)
    gl.DeleteShader(shader);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[4096] = {};
    gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
    gl.DeleteProgram(program);
    throw std::runtime_error(std::string("GL exact device: the program does not link: ") + log);
  }
  return program;
}

}  // namespace

GLuint buildExactProgram(const GlCoreFunctions& gl) {
  const GLuint vertex = compileStage(gl, GL_VERTEX_SHADER, kExactGlVertex, "vertex");
  GLuint fragment = 0;
  try {
    fragment = compileStage(gl, GL_FRAGMENT_SHADER, kExactGlFragment, "fragment");
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  return linkProgram(gl, {vertex, fragment});
}

GLuint buildSummaryProgram(const GlCoreFunctions& gl) {
  const GLuint compute = compileParts(gl, GL_COMPUTE_SHADER,
                                      {"#version 450 core\n", kSummaryGlCompute, kPixelSummaryGlsl},
                                      "summary compute");
  return linkProgram(gl, {compute});
}

}  // namespace recode::backends::detail
