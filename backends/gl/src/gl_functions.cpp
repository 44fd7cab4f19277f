#include "gl_functions.hpp"

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

GlLegacyFunctions loadGlLegacyFunctions(GlContext& context) {
  GlLegacyFunctions gl;
#define RECODE_GL_LOAD(type, name) gl.name = reinterpret_cast<type>(resolve(context, "gl" #name));
  RECODE_GL_LEGACY_FUNCTIONS(RECODE_GL_LOAD)
#undef RECODE_GL_LOAD
  return gl;
}

}  // namespace recode::backends::detail
