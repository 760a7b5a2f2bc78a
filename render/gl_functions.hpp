#pragma once
// The OpenGL entry points the renderer uses, fetched once per context with
// OSMesaGetProcAddress rather than linked by name.
//
// Why: libOSMesa exports every glXxx symbol, but so does libGL, and OpenCV
// (or anything else) may load libGL into the process. Whichever library the
// dynamic linker finds first then wins, and with libGL first every call goes
// to a dispatch table that has no current context: glGetString returns NULL
// and every image comes out black, without any error. Function pointers from
// OSMesaGetProcAddress always reach OSMesa's own dispatch, whatever the link
// order. (tests/render checks GL_RENDERER is not NULL and that a draw leaves
// the expected colour.)
//
// Internal to render/: include it only from render/*.cpp.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES  // only so that decltype(&::glXxx) names each type below
#endif
#include <GL/gl.h>
#include <GL/glext.h>

namespace facadeslam::render {

// X-macro of the entry points, without the "gl" prefix.
// (a table: not for clang-format)
// clang-format off
#define FACADESLAM_GL_FUNCTIONS(X)                                                            \
  X(GetString) X(GetStringi) X(GetIntegerv) X(GetFloatv) X(GetError) X(Finish)                \
  X(Viewport) X(Enable) X(Disable) X(DepthFunc) X(DepthMask) X(ClipControl) X(LineWidth)      \
  X(ClearBufferfv) X(ClearBufferuiv) X(PixelStorei) X(ReadBuffer) X(ReadPixels) X(DrawBuffers)\
  X(GenTextures) X(DeleteTextures) X(BindTexture) X(TexImage2D) X(TexParameteri)              \
  X(TexParameterf) X(GenerateMipmap) X(ActiveTexture)                                         \
  X(GenFramebuffers) X(DeleteFramebuffers) X(BindFramebuffer) X(FramebufferTexture2D)         \
  X(CheckFramebufferStatus) X(GenRenderbuffers) X(DeleteRenderbuffers) X(BindRenderbuffer)    \
  X(RenderbufferStorage) X(FramebufferRenderbuffer)                                           \
  X(GenBuffers) X(DeleteBuffers) X(BindBuffer) X(BufferData)                                  \
  X(GenVertexArrays) X(DeleteVertexArrays) X(BindVertexArray) X(EnableVertexAttribArray)      \
  X(VertexAttribPointer) X(DrawElements) X(DrawArrays)                                        \
  X(CreateShader) X(ShaderSource) X(CompileShader) X(GetShaderiv) X(GetShaderInfoLog)         \
  X(DeleteShader) X(CreateProgram) X(AttachShader) X(LinkProgram) X(GetProgramiv)             \
  X(GetProgramInfoLog) X(DeleteProgram) X(UseProgram) X(GetUniformLocation)                   \
  X(Uniform1i) X(Uniform1ui) X(Uniform1f) X(Uniform4f) X(UniformMatrix3fv)
// clang-format on

struct GlFunctions {
#define FACADESLAM_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
  FACADESLAM_GL_FUNCTIONS(FACADESLAM_GL_MEMBER)
#undef FACADESLAM_GL_MEMBER

  // Fetches every entry point; the OSMesa context must be current. Throws
  // Error naming the first function OSMesa does not provide.
  static GlFunctions load();
};

}  // namespace facadeslam::render
