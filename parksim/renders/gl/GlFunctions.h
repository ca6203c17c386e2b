#pragma once
// Internal to parksim_render (not installed): the OpenGL entry points the renderer uses, as
// pointers loaded through the context's backend (OSMesaGetProcAddress, eglGetProcAddress).
//
// Not link-time symbols: libOSMesa exports its own gl* functions and glvnd's libOpenGL exports
// dispatch stubs, so a library linked against both would call one backend's functions with the
// other's context current. Loading through the backend that made the context keeps each
// context's calls in its own library. <GL/glcorearb.h> is included without
// GL_GLEXT_PROTOTYPES, so a direct glFoo() call does not compile.

#include <GL/glcorearb.h>

#include <string>

namespace parksim {

// X(Name, NAME): glName, typed by <GL/glcorearb.h>'s PFNGLNAMEPROC. Exactly the functions the
// renderer calls; add one here before using it.
#define PARKSIM_GL_FUNCTIONS(X)                                     \
  X(ActiveTexture, ACTIVETEXTURE)                                   \
  X(AttachShader, ATTACHSHADER)                                     \
  X(BindBuffer, BINDBUFFER)                                         \
  X(BindFramebuffer, BINDFRAMEBUFFER)                               \
  X(BindRenderbuffer, BINDRENDERBUFFER)                             \
  X(BindTexture, BINDTEXTURE)                                       \
  X(BindVertexArray, BINDVERTEXARRAY)                               \
  X(BlendFuncSeparate, BLENDFUNCSEPARATE)                           \
  X(BlitFramebuffer, BLITFRAMEBUFFER)                               \
  X(BufferData, BUFFERDATA)                                         \
  X(BufferSubData, BUFFERSUBDATA)                                   \
  X(CheckFramebufferStatus, CHECKFRAMEBUFFERSTATUS)                 \
  X(Clear, CLEAR)                                                   \
  X(ClearColor, CLEARCOLOR)                                         \
  X(ClearDepth, CLEARDEPTH)                                         \
  X(CompileShader, COMPILESHADER)                                   \
  X(CreateProgram, CREATEPROGRAM)                                   \
  X(CreateShader, CREATESHADER)                                     \
  X(DeleteBuffers, DELETEBUFFERS)                                   \
  X(DeleteFramebuffers, DELETEFRAMEBUFFERS)                         \
  X(DeleteProgram, DELETEPROGRAM)                                   \
  X(DeleteRenderbuffers, DELETERENDERBUFFERS)                       \
  X(DeleteShader, DELETESHADER)                                     \
  X(DeleteTextures, DELETETEXTURES)                                 \
  X(DeleteVertexArrays, DELETEVERTEXARRAYS)                         \
  X(DepthFunc, DEPTHFUNC)                                           \
  X(DepthMask, DEPTHMASK)                                           \
  X(Disable, DISABLE)                                               \
  X(DrawArrays, DRAWARRAYS)                                         \
  X(Enable, ENABLE)                                                 \
  X(EnableVertexAttribArray, ENABLEVERTEXATTRIBARRAY)               \
  X(FramebufferRenderbuffer, FRAMEBUFFERRENDERBUFFER)               \
  X(GenBuffers, GENBUFFERS)                                         \
  X(GenFramebuffers, GENFRAMEBUFFERS)                               \
  X(GenRenderbuffers, GENRENDERBUFFERS)                             \
  X(GenTextures, GENTEXTURES)                                       \
  X(GenVertexArrays, GENVERTEXARRAYS)                               \
  X(GetError, GETERROR)                                             \
  X(GetIntegerv, GETINTEGERV)                                       \
  X(GetProgramInfoLog, GETPROGRAMINFOLOG)                           \
  X(GetProgramiv, GETPROGRAMIV)                                     \
  X(GetShaderInfoLog, GETSHADERINFOLOG)                             \
  X(GetShaderiv, GETSHADERIV)                                       \
  X(GetString, GETSTRING)                                           \
  X(GetUniformLocation, GETUNIFORMLOCATION)                         \
  X(LinkProgram, LINKPROGRAM)                                       \
  X(PixelStorei, PIXELSTOREI)                                       \
  X(ReadPixels, READPIXELS)                                         \
  X(RenderbufferStorage, RENDERBUFFERSTORAGE)                       \
  X(RenderbufferStorageMultisample, RENDERBUFFERSTORAGEMULTISAMPLE) \
  X(Scissor, SCISSOR)                                               \
  X(ShaderSource, SHADERSOURCE)                                     \
  X(TexImage2D, TEXIMAGE2D)                                         \
  X(TexParameteri, TEXPARAMETERI)                                   \
  X(Uniform1f, UNIFORM1F)                                           \
  X(Uniform1i, UNIFORM1I)                                           \
  X(Uniform3f, UNIFORM3F)                                           \
  X(UniformMatrix4fv, UNIFORMMATRIX4FV)                             \
  X(UseProgram, USEPROGRAM)                                         \
  X(VertexAttribPointer, VERTEXATTRIBPOINTER)                       \
  X(Viewport, VIEWPORT)

/// One context's entry points: gl.Clear(...) calls that backend's glClear.
struct GlFunctions {
#define PARKSIM_GL_MEMBER(name, NAME) PFNGL##NAME##PROC name = nullptr;
  PARKSIM_GL_FUNCTIONS(PARKSIM_GL_MEMBER)
#undef PARKSIM_GL_MEMBER
};

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

/// Loads every entry point through `load`. Throws Error naming `backend` and the first function
/// it does not provide.
GlFunctions loadGlFunctions(GlProcLoader load, const std::string& backend);

/// "VERSION, RENDERER" of the current context, e.g. "4.5 (Core Profile) Mesa 22.3.6, llvmpipe
/// (LLVM 15.0.6, 256 bits)".
std::string glVersionAndRenderer(const GlFunctions& gl);

}  // namespace parksim
