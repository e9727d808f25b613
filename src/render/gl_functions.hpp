// The GL entry points the renderer uses, loaded at runtime through the
// context backend's GetProcAddress. We never link libGL: its dispatch would
// shadow OSMesa's and every draw would silently produce nothing.
#pragma once

#include <GL/glcorearb.h>  // types, enums and PFN typedefs only (no prototypes)

namespace tumble::render {

// X(pfn-type, member-name, "glSymbol"): one line per function we call.
#define TUMBLE_GL_FUNCTIONS(X)                                                   \
  X(PFNGLGETERRORPROC, GetError, "glGetError")                                   \
  X(PFNGLGETSTRINGPROC, GetString, "glGetString")                                \
  X(PFNGLGETINTEGERVPROC, GetIntegerv, "glGetIntegerv")                          \
  X(PFNGLGETFLOATVPROC, GetFloatv, "glGetFloatv")                                \
  X(PFNGLENABLEPROC, Enable, "glEnable")                                         \
  X(PFNGLDISABLEPROC, Disable, "glDisable")                                      \
  X(PFNGLCLEARPROC, Clear, "glClear")                                            \
  X(PFNGLCLEARCOLORPROC, ClearColor, "glClearColor")                             \
  X(PFNGLVIEWPORTPROC, Viewport, "glViewport")                                   \
  X(PFNGLSCISSORPROC, Scissor, "glScissor")                                      \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate, "glBlendFuncSeparate")        \
  X(PFNGLDEPTHMASKPROC, DepthMask, "glDepthMask")                                \
  X(PFNGLDEPTHFUNCPROC, DepthFunc, "glDepthFunc")                                \
  X(PFNGLCULLFACEPROC, CullFace, "glCullFace")                                   \
  X(PFNGLPOLYGONOFFSETPROC, PolygonOffset, "glPolygonOffset")                    \
  X(PFNGLLINEWIDTHPROC, LineWidth, "glLineWidth")                                \
  X(PFNGLPIXELSTOREIPROC, PixelStorei, "glPixelStorei")                          \
  X(PFNGLREADPIXELSPROC, ReadPixels, "glReadPixels")                             \
  X(PFNGLREADBUFFERPROC, ReadBuffer, "glReadBuffer")                             \
  X(PFNGLFINISHPROC, Finish, "glFinish")                                         \
  X(PFNGLGENBUFFERSPROC, GenBuffers, "glGenBuffers")                             \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, "glDeleteBuffers")                    \
  X(PFNGLBINDBUFFERPROC, BindBuffer, "glBindBuffer")                             \
  X(PFNGLBUFFERDATAPROC, BufferData, "glBufferData")                             \
  X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange, "glMapBufferRange")                 \
  X(PFNGLUNMAPBUFFERPROC, UnmapBuffer, "glUnmapBuffer")                          \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, "glGenVertexArrays")              \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, "glDeleteVertexArrays")     \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, "glBindVertexArray")              \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray,                   \
    "glEnableVertexAttribArray")                                                 \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, "glVertexAttribPointer")  \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor, "glVertexAttribDivisor")  \
  X(PFNGLDRAWARRAYSPROC, DrawArrays, "glDrawArrays")                             \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced, "glDrawArraysInstanced")  \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced,                       \
    "glDrawElementsInstanced")                                                   \
  X(PFNGLCREATESHADERPROC, CreateShader, "glCreateShader")                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource, "glShaderSource")                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader, "glCompileShader")                    \
  X(PFNGLGETSHADERIVPROC, GetShaderiv, "glGetShaderiv")                          \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog, "glGetShaderInfoLog")           \
  X(PFNGLDELETESHADERPROC, DeleteShader, "glDeleteShader")                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram, "glCreateProgram")                    \
  X(PFNGLATTACHSHADERPROC, AttachShader, "glAttachShader")                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram, "glLinkProgram")                          \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv, "glGetProgramiv")                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog, "glGetProgramInfoLog")        \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram, "glDeleteProgram")                    \
  X(PFNGLUSEPROGRAMPROC, UseProgram, "glUseProgram")                             \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, "glGetUniformLocation")     \
  X(PFNGLUNIFORM1IPROC, Uniform1i, "glUniform1i")                                \
  X(PFNGLUNIFORM1FPROC, Uniform1f, "glUniform1f")                                \
  X(PFNGLUNIFORM2FPROC, Uniform2f, "glUniform2f")                                \
  X(PFNGLUNIFORM3FPROC, Uniform3f, "glUniform3f")                                \
  X(PFNGLUNIFORM4FPROC, Uniform4f, "glUniform4f")                                \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv, "glUniformMatrix4fv")           \
  X(PFNGLGENTEXTURESPROC, GenTextures, "glGenTextures")                          \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures, "glDeleteTextures")                 \
  X(PFNGLBINDTEXTUREPROC, BindTexture, "glBindTexture")                          \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture, "glActiveTexture")                    \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D, "glTexImage2D")                             \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri, "glTexParameteri")                    \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap, "glGenerateMipmap")                 \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, "glGenFramebuffers")              \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers, "glDeleteFramebuffers")     \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, "glBindFramebuffer")              \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D, "glFramebufferTexture2D")  \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer,                   \
    "glFramebufferRenderbuffer")                                                 \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus,                     \
    "glCheckFramebufferStatus")                                                  \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers, "glGenRenderbuffers")           \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers, "glDeleteRenderbuffers")  \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer, "glBindRenderbuffer")           \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample,     \
    "glRenderbufferStorageMultisample")                                          \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer, "glBlitFramebuffer")

/// Function table owned by a context; valid only while that context is current.
struct GlFunctions {
#define TUMBLE_GL_MEMBER(type, name, symbol) type name = nullptr;
  TUMBLE_GL_FUNCTIONS(TUMBLE_GL_MEMBER)
#undef TUMBLE_GL_MEMBER
};

/// Resolver for one symbol name (OSMesaGetProcAddress / eglGetProcAddress).
using GlProcResolver = void* (*)(void* user, const char* name);

/// Fills every entry; throws std::runtime_error naming the first missing one.
GlFunctions load_gl_functions(GlProcResolver resolve, void* user);

}  // namespace tumble::render
