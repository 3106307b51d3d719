#pragma once
// GL-era GLSL on the native path reads the fixed-function state: gl_ModelViewMatrix and
// the other matrices, gl_LightSource[n], gl_FrontMaterial, gl_LightModel, and the
// vertex arrays behind gl_Vertex, gl_Normal, gl_MultiTexCoord0 and gl_Color. In a
// compatibility-profile context this file sets that state through the legacy calls,
// from the same case bindings the SPIR-V paths upload as uniforms (the dialect layer,
// compile/LegacyGlsl.h, names them), so every path draws the same thing:
//  - GL_MODELVIEW / GL_PROJECTION from gl_ModelViewMatrix / gl_ProjectionMatrix (GL
//    derives the others, gl_NormalMatrix included);
//  - each gl_LightSource[n] member the shader uses with glLight* under an identity
//    modelview, so a position or spot direction is taken as given (view space);
//  - gl_FrontMaterial members with glMaterial* (front and back), gl_LightModel.ambient
//    with glLightModelfv (light products are GL's own, from these);
//  - vertex and fragment colour clamping off, as on the other paths.
#include <type_traits>

#include "backends/UniformPacking.h"
#include "backends/gl/GlFunctions.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::gl {

// X(function type, member, "glName")
#define SHADERBED_LEGACY_GL_FUNCTIONS(X)                                               \
  X(void(GLenum), MatrixMode, "glMatrixMode")                                      \
  X(void(const GLfloat*), LoadMatrixf, "glLoadMatrixf")                            \
  X(void(), LoadIdentity, "glLoadIdentity")                                        \
  X(void(GLenum, GLenum, const GLfloat*), Lightfv, "glLightfv")                    \
  X(void(GLenum, GLenum, GLfloat), Lightf, "glLightf")                             \
  X(void(GLenum, GLenum, const GLfloat*), Materialfv, "glMaterialfv")              \
  X(void(GLenum, GLenum, GLfloat), Materialf, "glMaterialf")                       \
  X(void(GLenum, const GLfloat*), LightModelfv, "glLightModelfv")                  \
  X(void(GLenum), EnableClientState, "glEnableClientState")                        \
  X(void(GLint, GLenum, GLsizei, const void*), VertexPointer, "glVertexPointer")   \
  X(void(GLenum, GLsizei, const void*), NormalPointer, "glNormalPointer")          \
  X(void(GLint, GLenum, GLsizei, const void*), ColorPointer, "glColorPointer")     \
  X(void(GLint, GLenum, GLsizei, const void*), TexCoordPointer, "glTexCoordPointer") \
  X(void(GLenum), ClientActiveTexture, "glClientActiveTexture")

// The legacy entry points, loaded through the context's platform like the core ones.
struct LegacyGlFunctions {
#define SHADERBED_DECLARE(type, member, name) std::add_pointer_t<type> member = nullptr;
  SHADERBED_LEGACY_GL_FUNCTIONS(SHADERBED_DECLARE)
#undef SHADERBED_DECLARE
};

Result<LegacyGlFunctions> load_legacy_gl_functions(GlProcLoader loader);

// Matrices, lights, material and light model for `program` (the dialect's reflection
// says which it reads), each value from `uniforms` by its legacy name.
Result<void> set_legacy_gl_state(const GlFunctions& gl, const LegacyGlFunctions& legacy,
                                      const CompiledProgram& program, const UniformResolver& uniforms);

// The legacy arrays the vertex shader reads (gl_Vertex, ...), from `vertex_buffer` (the
// mesh's interleaved shaderbed::Vertex data) into the bound vertex array object.
Result<void> bind_legacy_vertex_arrays(const GlFunctions& gl, const LegacyGlFunctions& legacy,
                                       const CompiledProgram& program, GLuint vertex_buffer);

}  // namespace shaderbed::gl
