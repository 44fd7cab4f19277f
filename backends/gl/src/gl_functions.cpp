#include "gl_functions.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace recode::backends::detail {

namespace {

GlContext::Proc resolve(GlContext& context, const char* name) {
  GlContext::Proc proc = context.procAddress(name);
  if (proc == nullptr)
    throw std::runtime_error(std::string("GL: the context provides no ") + name);
  return proc;
}

}  // namespace

GlCoreFunctions loadGlCoreFunctions(GlContext& context) {
  GlCoreFunctions gl;
#define RECODE_GL_LOAD(type, name) gl.name = reinterpret_cast<type>(resolve(context, "gl" #name));
  RECODE_GL_CORE_FUNCTIONS(RECODE_GL_LOAD)
#undef RECODE_GL_LOAD
  return gl;
}

namespace {

std::string hexCode(GLenum value) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(value));
  return code;
}

}  // namespace

void throwOnGlError(const GlCoreFunctions& gl, const char* device, const char* what) {
  const GLenum error = gl.GetError();
  if (error != GL_NO_ERROR)
    throw std::runtime_error(std::string(device) + ": GL error " + hexCode(error) + " in " + what);
}

DepthStencilFramebuffer createDepthStencilFramebuffer(const GlCoreFunctions& g, GLenum format,
                                                      const char* formatName, int width, int height,
                                                      const char* device) {
  DepthStencilFramebuffer made;
  g.GenRenderbuffers(1, &made.renderbuffer);
  g.BindRenderbuffer(GL_RENDERBUFFER, made.renderbuffer);
  g.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  g.GenFramebuffers(1, &made.framebuffer);
  g.BindFramebuffer(GL_FRAMEBUFFER, made.framebuffer);
  g.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            made.renderbuffer);
  g.DrawBuffer(GL_NONE);
  g.ReadBuffer(GL_NONE);
  const GLenum status = g.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string(device) + ": a " + formatName +
                             " framebuffer is incomplete (status " + hexCode(status) + ")");
  return made;
}

GlLegacyFunctions loadGlLegacyFunctions(GlContext& context) {
  GlLegacyFunctions gl;
#define RECODE_GL_LOAD(type, name) gl.name = reinterpret_cast<type>(resolve(context, "gl" #name));
  RECODE_GL_LEGACY_FUNCTIONS(RECODE_GL_LOAD)
#undef RECODE_GL_LOAD
  return gl;
}

}  // namespace recode::backends::detail
