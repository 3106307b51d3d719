#pragma once
// Turns one CompiledProgram into a linked GL program along one path:
//   native_glsl: the author's GLSL through Mesa's GLSL compiler,
//   spirv:       the OpenGL-target SPIR-V through GL_ARB_gl_spirv (binary + specialise),
//   cross_glsl:  SPIRV-Cross's GLSL through Mesa's GLSL compiler.
// Failures name the shader's source file; for native GLSL also Mesa's line and column.
#include "backends/Backend.h"
#include "backends/gl/GlObject.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::gl {

// The caller checks GL_ARB_gl_spirv before asking for ShaderPath::spirv.
Result<GlProgram> build_gl_program(const GlFunctions& gl, const CompiledProgram& program, ShaderPath path);

}  // namespace shaderbed::gl
