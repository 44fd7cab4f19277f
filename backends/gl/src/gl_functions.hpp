#pragma once
// The OpenGL 4.5 core entry points the exact GL device calls, resolved through its context
// (OSMesaGetProcAddress or eglGetProcAddress) rather than linked: with OSMesa the gl* symbols
// live in libOSMesa, with EGL behind GLVND's dispatch, and linking both ways into one program
// would make one of them answer nothing. Private to recode_backend_gl.

#include <GL/glcorearb.h>

#include "gl_context.hpp"

namespace recode::backends::detail {

// X(type, name): every function the device uses, glName without its "gl" prefix as the member.
#define RECODE_GL_CORE_FUNCTIONS(X)                            \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLSCISSORPROC, Scissor)                                 \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                           \
  X(PFNGLCLEARSTENCILPROC, ClearStencil)                       \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, DepthMask)                             \
  X(PFNGLSTENCILFUNCPROC, StencilFunc)                         \
  X(PFNGLSTENCILOPSEPARATEPROC, StencilOpSeparate)             \
  X(PFNGLSTENCILMASKPROC, StencilMask)                         \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLDRAWBUFFERPROC, DrawBuffer)                           \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)         \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)               \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)       \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)

struct GlCoreFunctions {
#define RECODE_GL_MEMBER(type, name) type name = nullptr;
  RECODE_GL_CORE_FUNCTIONS(RECODE_GL_MEMBER)
#undef RECODE_GL_MEMBER
};

// Resolves every function through the context, which must be current. Throws
// std::runtime_error naming the first function the context does not provide.
[[nodiscard]] GlCoreFunctions loadGlCoreFunctions(GlContext& context);

}  // namespace recode::backends::detail
