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
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)         \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                     \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                   \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                 \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)

// The compatibility-profile entry points the fixed-function GlDevice needs beyond the core ones:
// the matrix stack, client vertex arrays, and the fixed state it sets once. glcorearb.h declares
// no type for the first five.
using RecodeGlMatrixModeProc = void(APIENTRYP)(GLenum mode);
using RecodeGlLoadMatrixfProc = void(APIENTRYP)(const GLfloat* m);
using RecodeGlLoadIdentityProc = void(APIENTRYP)();
using RecodeGlEnableClientStateProc = void(APIENTRYP)(GLenum array);
using RecodeGlVertexPointerProc = void(APIENTRYP)(GLint size, GLenum type, GLsizei stride,
                                                  const void* pointer);
inline constexpr GLenum kGlModelview = 0x1700;    // GL_MODELVIEW
inline constexpr GLenum kGlProjection = 0x1701;   // GL_PROJECTION
inline constexpr GLenum kGlVertexArray = 0x8074;  // GL_VERTEX_ARRAY

#define RECODE_GL_LEGACY_FUNCTIONS(X)                 \
  X(PFNGLDEPTHRANGEPROC, DepthRange)                  \
  X(RecodeGlMatrixModeProc, MatrixMode)               \
  X(RecodeGlLoadMatrixfProc, LoadMatrixf)             \
  X(RecodeGlLoadIdentityProc, LoadIdentity)           \
  X(PFNGLPOLYGONMODEPROC, PolygonMode)                \
  X(PFNGLFRONTFACEPROC, FrontFace)                    \
  X(PFNGLCOLORMASKPROC, ColorMask)                    \
  X(PFNGLSTENCILOPPROC, StencilOp)                    \
  X(RecodeGlEnableClientStateProc, EnableClientState) \
  X(PFNGLCULLFACEPROC, CullFace)                      \
  X(RecodeGlVertexPointerProc, VertexPointer)         \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)              \
  X(PFNGLCLIPCONTROLPROC, ClipControl)

struct GlLegacyFunctions {
#define RECODE_GL_MEMBER(type, name) type name = nullptr;
  RECODE_GL_LEGACY_FUNCTIONS(RECODE_GL_MEMBER)
#undef RECODE_GL_MEMBER
};

struct GlCoreFunctions {
#define RECODE_GL_MEMBER(type, name) type name = nullptr;
  RECODE_GL_CORE_FUNCTIONS(RECODE_GL_MEMBER)
#undef RECODE_GL_MEMBER
};

// Resolves every function through the context, which must be current. Throws
// std::runtime_error naming the first function the context does not provide.
[[nodiscard]] GlCoreFunctions loadGlCoreFunctions(GlContext& context);
// A GL error is a bug in the device that met it (every input was validated), so it is reported
// loudly: throws std::runtime_error "DEVICE: GL error 0x.... in WHAT" when glGetError has one.
void throwOnGlError(const GlCoreFunctions& gl, const char* device, const char* what);

// A framebuffer object with one depth/stencil renderbuffer of `format` (named `formatName` in
// errors) and no colour, left bound. Throws std::runtime_error "DEVICE: a FORMAT framebuffer is
// incomplete (status 0x....)" when the driver refuses it.
struct DepthStencilFramebuffer {
  GLuint framebuffer = 0;
  GLuint renderbuffer = 0;
};
[[nodiscard]] DepthStencilFramebuffer createDepthStencilFramebuffer(const GlCoreFunctions& gl,
                                                                    GLenum format,
                                                                    const char* formatName,
                                                                    int width, int height,
                                                                    const char* device);

// The same for the compatibility-profile entry points (the context must be a compatibility one).
[[nodiscard]] GlLegacyFunctions loadGlLegacyFunctions(GlContext& context);

}  // namespace recode::backends::detail
