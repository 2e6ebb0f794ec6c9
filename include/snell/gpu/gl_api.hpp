// A per-context table of GL entry points.
//
// Why a table and never a direct glFoo() call: libOSMesa exports its own gl*
// symbols, so a binary that links libGL (for EGL) and libOSMesa and calls
// glFoo directly may reach the wrong library: glGetString returns NULL and
// reads return noise while glGetError still reports no error (DESIGN.md sec. 3,
// "Symbol clash"). Every pointer here comes from the backend's own
// GetProcAddress, so both backends can live in one process and link order does
// not matter. The table also lets users drive their own GL context (GLFW, SDL,
// Qt): fill it with that toolkit's loader and every snell::gpu helper works.
//
// Members drop the "gl" prefix (gl.Clear, gl.DispatchCompute), as glad 2 does.
#pragma once

// Types and enums only: without GL_GLEXT_PROTOTYPES glcorearb.h declares no
// functions, so an accidental direct call fails to compile instead of linking
// to whichever gl* symbol the loader found first.
#ifdef GL_GLEXT_PROTOTYPES
#  error "snell/gpu: do not define GL_GLEXT_PROTOTYPES; GL is reached through snell::gpu::GlApi"
#endif
#include <GL/glcorearb.h>

#include "error.hpp"

#include <string>

namespace snell::gpu {

// X(pointer type, name without the "gl" prefix): exactly the entry points the
// helpers use. Adding one here is all it takes to make it available.
#define SNELL_GL_FUNCTIONS(X)                                   \
  /* state and queries */                                       \
  X(PFNGLGETERRORPROC, GetError)                                \
  X(PFNGLGETSTRINGPROC, GetString)                              \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                          \
  X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                      \
  X(PFNGLFINISHPROC, Finish)                                    \
  X(PFNGLFLUSHPROC, Flush)                                      \
  X(PFNGLENABLEPROC, Enable)                                    \
  X(PFNGLDISABLEPROC, Disable)                                  \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                              \
  X(PFNGLDEPTHMASKPROC, DepthMask)                              \
  X(PFNGLCOLORMASKIPROC, ColorMaski)                             \
  X(PFNGLCULLFACEPROC, CullFace)                                \
  X(PFNGLVIEWPORTPROC, Viewport)                                \
  X(PFNGLSCISSORPROC, Scissor)                                  \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                          \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                      \
  /* clears and draws */                                        \
  X(PFNGLCLEARPROC, Clear)                                      \
  X(PFNGLCLEARCOLORPROC, ClearColor)                            \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                            \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                      \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                            \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                  \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)            \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                  \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                  \
  /* shaders and programs */                                    \
  X(PFNGLCREATESHADERPROC, CreateShader)                        \
  X(PFNGLDELETESHADERPROC, DeleteShader)                        \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                        \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                      \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                          \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                      \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                      \
  X(PFNGLATTACHSHADERPROC, AttachShader)                        \
  X(PFNGLDETACHSHADERPROC, DetachShader)                        \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                          \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                        \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)              \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                            \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)            \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)        \
  X(PFNGLGETACTIVEUNIFORMBLOCKIVPROC, GetActiveUniformBlockiv)  \
  X(PFNGLPROGRAMUNIFORM1IPROC, ProgramUniform1i)                \
  X(PFNGLPROGRAMUNIFORM1FPROC, ProgramUniform1f)                \
  X(PFNGLPROGRAMUNIFORM2FVPROC, ProgramUniform2fv)              \
  X(PFNGLPROGRAMUNIFORM3FVPROC, ProgramUniform3fv)              \
  X(PFNGLPROGRAMUNIFORM4FVPROC, ProgramUniform4fv)              \
  X(PFNGLPROGRAMUNIFORM2IVPROC, ProgramUniform2iv)              \
  X(PFNGLPROGRAMUNIFORMMATRIX4FVPROC, ProgramUniformMatrix4fv)  \
  /* buffers */                                                 \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                            \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                      \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                            \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                    \
  X(PFNGLBUFFERDATAPROC, BufferData)                            \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                      \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                \
  /* textures */                                                \
  X(PFNGLGENTEXTURESPROC, GenTextures)                          \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                    \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                          \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                      \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                            \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                      \
  X(PFNGLGETTEXPARAMETERIVPROC, GetTexParameteriv)              \
  X(PFNGLGETTEXLEVELPARAMETERIVPROC, GetTexLevelParameteriv)    \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                    \
  X(PFNGLGETTEXIMAGEPROC, GetTexImage)                          \
  X(PFNGLBINDIMAGETEXTUREPROC, BindImageTexture)                \
  /* framebuffers */                                            \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                  \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)            \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                  \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                  \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)        \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)  \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)    \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)          \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)          \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                          \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                            \
  X(PFNGLREADPIXELSPROC, ReadPixels)

struct GlApi {
#define SNELL_GL_MEMBER(type, name) type name = nullptr;
  SNELL_GL_FUNCTIONS(SNELL_GL_MEMBER)
#undef SNELL_GL_MEMBER

  // Fills the table from `getProc` (anything callable as void*(const char*)).
  // All missing entry points are named in one Error, so a driver that lacks
  // several shows them all at once.
  template <class GetProc>
  static GlApi loadWith(GetProc&& getProc) {
    GlApi api;
    std::string missing;
#define SNELL_GL_LOAD(type, name)                                   \
  api.name = reinterpret_cast<type>(getProc("gl" #name));           \
  if (api.name == nullptr) missing += std::string(missing.empty() ? "" : ", ") + "gl" #name;
    SNELL_GL_FUNCTIONS(SNELL_GL_LOAD)
#undef SNELL_GL_LOAD
    if (!missing.empty())
      throw Error("GL loader: missing entry point(s) " + missing +
                  "; the driver or context is too old (snell::gpu needs OpenGL 4.3 core)");
    return api;
  }

  static GlApi load(void* (*getProc)(const char*)) { return loadWith(getProc); }
};

// Name of a glGetError code, for messages.
inline const char* glErrorName(GLenum code) {
  switch (code) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
    default: return "unknown GL error";
  }
}

// Throws Error("GL error 0x0502 (GL_INVALID_OPERATION) after <what>") if GL
// recorded an error. Drains the whole error queue so a stale error from an
// earlier call cannot be blamed on the next checkGl.
inline void checkGl(const GlApi& gl, const char* what) {
  GLenum first = gl.GetError();
  if (first == GL_NO_ERROR) return;
  for (int i = 0; i < 32 && gl.GetError() != GL_NO_ERROR; ++i) {
  }
  char code[16];
  static const char hex[] = "0123456789ABCDEF";
  code[0] = '0';
  code[1] = 'x';
  for (int i = 0; i < 4; ++i) code[2 + i] = hex[(first >> (12 - 4 * i)) & 0xFu];
  code[6] = '\0';
  throw Error(std::string("GL error ") + code + " (" + glErrorName(first) + ") after " + what);
}
inline void checkGl(const GlApi& gl, const std::string& what) { checkGl(gl, what.c_str()); }

}  // namespace snell::gpu
