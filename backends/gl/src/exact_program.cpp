#include "exact_program.hpp"

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

GLuint compileStage(const GlCoreFunctions& gl, GLenum stage, const char* body, const char* what) {
  const GLuint shader = gl.CreateShader(stage);
  const char* parts[] = {kHeader, kExactContractGlsl, body};
  gl.ShaderSource(shader, 3, parts, nullptr);
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
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
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

}  // namespace recode::backends::detail
