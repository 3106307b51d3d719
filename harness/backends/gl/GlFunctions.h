#pragma once
// The GL entry points the GL renderer uses, loaded by name through the context's platform
// (OSMesaGetProcAddress, eglGetProcAddress). libepoxy and GLAD-style global loaders are
// avoided on purpose: libepoxy aborts under OSMesa, and a plain table keeps every call
// explicit.
#include <GL/glcorearb.h>

#include "core/Error.h"

namespace shaderbed::gl {

// X(type, member, "glName"): only the functions this backend calls.
#define SHADERBED_GL_FUNCTIONS(X)                                                        \
  X(PFNGLGETERRORPROC, GetError, "glGetError")                                           \
  X(PFNGLGETSTRINGPROC, GetString, "glGetString")                                        \
  X(PFNGLGETSTRINGIPROC, GetStringi, "glGetStringi")                                     \
  X(PFNGLGETINTEGERVPROC, GetIntegerv, "glGetIntegerv")                                  \
  X(PFNGLENABLEPROC, Enable, "glEnable")                                                 \
  X(PFNGLDISABLEPROC, Disable, "glDisable")                                              \
  X(PFNGLDEPTHFUNCPROC, DepthFunc, "glDepthFunc")                                        \
  X(PFNGLDEPTHMASKPROC, DepthMask, "glDepthMask")                                        \
  X(PFNGLDEPTHRANGEPROC, DepthRange, "glDepthRange")                                     \
  X(PFNGLCOLORMASKPROC, ColorMask, "glColorMask")                                        \
  X(PFNGLCLIPCONTROLPROC, ClipControl, "glClipControl")                                  \
  X(PFNGLCLAMPCOLORPROC, ClampColor, "glClampColor")                                     \
  X(PFNGLPOLYGONMODEPROC, PolygonMode, "glPolygonMode")                                  \
  X(PFNGLCULLFACEPROC, CullFace, "glCullFace")                                           \
  X(PFNGLFRONTFACEPROC, FrontFace, "glFrontFace")                                        \
  X(PFNGLBLENDFUNCPROC, BlendFunc, "glBlendFunc")                                        \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation, "glBlendEquation")                            \
  X(PFNGLVIEWPORTPROC, Viewport, "glViewport")                                           \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv, "glClearBufferfv")                            \
  X(PFNGLFINISHPROC, Finish, "glFinish")                                                 \
  X(PFNGLPIXELSTOREIPROC, PixelStorei, "glPixelStorei")                                  \
  X(PFNGLREADBUFFERPROC, ReadBuffer, "glReadBuffer")                                     \
  X(PFNGLREADPIXELSPROC, ReadPixels, "glReadPixels")                                     \
  /* render target */                                                                    \
  X(PFNGLGENTEXTURESPROC, GenTextures, "glGenTextures")                                  \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures, "glDeleteTextures")                         \
  X(PFNGLBINDTEXTUREPROC, BindTexture, "glBindTexture")                                  \
  X(PFNGLTEXSTORAGE2DPROC, TexStorage2D, "glTexStorage2D")                               \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, "glGenFramebuffers")                      \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers, "glDeleteFramebuffers")             \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, "glBindFramebuffer")                      \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D, "glFramebufferTexture2D")       \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers, "glDrawBuffers")                                  \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus, "glCheckFramebufferStatus") \
  /* lookup textures (GL 4.5 direct state access) */                                     \
  X(PFNGLCREATETEXTURESPROC, CreateTextures, "glCreateTextures")                         \
  X(PFNGLTEXTURESTORAGE1DPROC, TextureStorage1D, "glTextureStorage1D")                   \
  X(PFNGLTEXTURESTORAGE2DPROC, TextureStorage2D, "glTextureStorage2D")                   \
  X(PFNGLTEXTURESTORAGE3DPROC, TextureStorage3D, "glTextureStorage3D")                   \
  X(PFNGLTEXTURESUBIMAGE1DPROC, TextureSubImage1D, "glTextureSubImage1D")                \
  X(PFNGLTEXTURESUBIMAGE2DPROC, TextureSubImage2D, "glTextureSubImage2D")                \
  X(PFNGLTEXTURESUBIMAGE3DPROC, TextureSubImage3D, "glTextureSubImage3D")                \
  X(PFNGLTEXTUREPARAMETERIPROC, TextureParameteri, "glTextureParameteri")                \
  X(PFNGLTEXTUREPARAMETERFVPROC, TextureParameterfv, "glTextureParameterfv")             \
  X(PFNGLBINDTEXTUREUNITPROC, BindTextureUnit, "glBindTextureUnit")                      \
  X(PFNGLBINDSAMPLERPROC, BindSampler, "glBindSampler")                                  \
  X(PFNGLGETINTERNALFORMATIVPROC, GetInternalformativ, "glGetInternalformativ")          \
  /* shaders and programs */                                                             \
  X(PFNGLCREATESHADERPROC, CreateShader, "glCreateShader")                               \
  X(PFNGLDELETESHADERPROC, DeleteShader, "glDeleteShader")                               \
  X(PFNGLSHADERSOURCEPROC, ShaderSource, "glShaderSource")                               \
  X(PFNGLCOMPILESHADERPROC, CompileShader, "glCompileShader")                            \
  X(PFNGLSHADERBINARYPROC, ShaderBinary, "glShaderBinary")                               \
  X(PFNGLSPECIALIZESHADERARBPROC, SpecializeShaderARB, "glSpecializeShaderARB")          \
  X(PFNGLGETSHADERIVPROC, GetShaderiv, "glGetShaderiv")                                  \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog, "glGetShaderInfoLog")                   \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram, "glCreateProgram")                            \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram, "glDeleteProgram")                            \
  X(PFNGLATTACHSHADERPROC, AttachShader, "glAttachShader")                               \
  X(PFNGLLINKPROGRAMPROC, LinkProgram, "glLinkProgram")                                  \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv, "glGetProgramiv")                               \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog, "glGetProgramInfoLog")                \
  X(PFNGLUSEPROGRAMPROC, UseProgram, "glUseProgram")                                     \
  /* introspection (GL 4.3 program interface query) */                                   \
  X(PFNGLGETPROGRAMINTERFACEIVPROC, GetProgramInterfaceiv, "glGetProgramInterfaceiv")    \
  X(PFNGLGETPROGRAMRESOURCEIVPROC, GetProgramResourceiv, "glGetProgramResourceiv")       \
  X(PFNGLGETPROGRAMRESOURCENAMEPROC, GetProgramResourceName, "glGetProgramResourceName") \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding, "glUniformBlockBinding")          \
  X(PFNGLGETUNIFORMIVPROC, GetUniformiv, "glGetUniformiv")                               \
  /* uniforms */                                                                         \
  X(PFNGLPROGRAMUNIFORM1IPROC, ProgramUniform1i, "glProgramUniform1i")                   \
  X(PFNGLPROGRAMUNIFORM1FVPROC, ProgramUniform1fv, "glProgramUniform1fv")                \
  X(PFNGLPROGRAMUNIFORM2FVPROC, ProgramUniform2fv, "glProgramUniform2fv")                \
  X(PFNGLPROGRAMUNIFORM3FVPROC, ProgramUniform3fv, "glProgramUniform3fv")                \
  X(PFNGLPROGRAMUNIFORM4FVPROC, ProgramUniform4fv, "glProgramUniform4fv")                \
  X(PFNGLPROGRAMUNIFORM1IVPROC, ProgramUniform1iv, "glProgramUniform1iv")                \
  X(PFNGLPROGRAMUNIFORM2IVPROC, ProgramUniform2iv, "glProgramUniform2iv")                \
  X(PFNGLPROGRAMUNIFORM3IVPROC, ProgramUniform3iv, "glProgramUniform3iv")                \
  X(PFNGLPROGRAMUNIFORM4IVPROC, ProgramUniform4iv, "glProgramUniform4iv")                \
  X(PFNGLPROGRAMUNIFORM1UIVPROC, ProgramUniform1uiv, "glProgramUniform1uiv")             \
  X(PFNGLPROGRAMUNIFORM2UIVPROC, ProgramUniform2uiv, "glProgramUniform2uiv")             \
  X(PFNGLPROGRAMUNIFORM3UIVPROC, ProgramUniform3uiv, "glProgramUniform3uiv")             \
  X(PFNGLPROGRAMUNIFORM4UIVPROC, ProgramUniform4uiv, "glProgramUniform4uiv")             \
  X(PFNGLPROGRAMUNIFORMMATRIX2FVPROC, ProgramUniformMatrix2fv, "glProgramUniformMatrix2fv")       \
  X(PFNGLPROGRAMUNIFORMMATRIX3FVPROC, ProgramUniformMatrix3fv, "glProgramUniformMatrix3fv")       \
  X(PFNGLPROGRAMUNIFORMMATRIX4FVPROC, ProgramUniformMatrix4fv, "glProgramUniformMatrix4fv")       \
  X(PFNGLPROGRAMUNIFORMMATRIX2X3FVPROC, ProgramUniformMatrix2x3fv, "glProgramUniformMatrix2x3fv") \
  X(PFNGLPROGRAMUNIFORMMATRIX2X4FVPROC, ProgramUniformMatrix2x4fv, "glProgramUniformMatrix2x4fv") \
  X(PFNGLPROGRAMUNIFORMMATRIX3X2FVPROC, ProgramUniformMatrix3x2fv, "glProgramUniformMatrix3x2fv") \
  X(PFNGLPROGRAMUNIFORMMATRIX3X4FVPROC, ProgramUniformMatrix3x4fv, "glProgramUniformMatrix3x4fv") \
  X(PFNGLPROGRAMUNIFORMMATRIX4X2FVPROC, ProgramUniformMatrix4x2fv, "glProgramUniformMatrix4x2fv") \
  X(PFNGLPROGRAMUNIFORMMATRIX4X3FVPROC, ProgramUniformMatrix4x3fv, "glProgramUniformMatrix4x3fv") \
  /* buffers and vertex input */                                                         \
  X(PFNGLGENBUFFERSPROC, GenBuffers, "glGenBuffers")                                     \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, "glDeleteBuffers")                            \
  X(PFNGLBINDBUFFERPROC, BindBuffer, "glBindBuffer")                                     \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase, "glBindBufferBase")                         \
  X(PFNGLBUFFERDATAPROC, BufferData, "glBufferData")                                     \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, "glGenVertexArrays")                      \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, "glDeleteVertexArrays")             \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, "glBindVertexArray")                      \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, "glEnableVertexAttribArray") \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, "glVertexAttribPointer")          \
  X(PFNGLDRAWELEMENTSPROC, DrawElements, "glDrawElements")                              \
  /* GPU timing (GL_TIME_ELAPSED, core since 3.3) */                                     \
  X(PFNGLGENQUERIESPROC, GenQueries, "glGenQueries")                                     \
  X(PFNGLDELETEQUERIESPROC, DeleteQueries, "glDeleteQueries")                            \
  X(PFNGLBEGINQUERYPROC, BeginQuery, "glBeginQuery")                                     \
  X(PFNGLENDQUERYPROC, EndQuery, "glEndQuery")                                           \
  X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v, "glGetQueryObjectui64v")

struct GlFunctions {
#define SHADERBED_GL_MEMBER(type, member, name) type member = nullptr;
  SHADERBED_GL_FUNCTIONS(SHADERBED_GL_MEMBER)
#undef SHADERBED_GL_MEMBER
};

// Looks a GL function up by name (OSMesaGetProcAddress or eglGetProcAddress behind a
// plain pointer type so this header does not pull in osmesa.h, whose GL/gl.h clashes with
// glcorearb.h).
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Fills the table. A null entry is an error naming the function. Mesa's loader hands
// out a no-op stub for names it does not know, so callers must still check the GL
// version / extension before relying on an entry (see GlRenderer::create).
Result<GlFunctions> load_gl_functions(GlProcLoader loader);

}  // namespace shaderbed::gl
