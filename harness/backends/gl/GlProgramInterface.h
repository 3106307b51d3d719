#pragma once
// What a linked GL program asks to be fed, in the compile stage's vocabulary so the
// shared uniform packing and attribute mapping apply unchanged. Two sources:
//  - GL's own program interface query, for the author's GLSL (Mesa decides the layout
//    of blocks without explicit offsets, and only GL knows default-block locations);
//  - the compile stage's reflection of the OpenGL-target SPIR-V, for the SPIR-V path
//    (GL_ARB_gl_spirv programs carry no names) and the SPIRV-Cross GLSL path (GL sees
//    an HLSL matrix there as the transposed row-major type; the reflection knows which
//    registers hold the HLSL matrix's columns).
#include <vector>

#include "backends/gl/GlFunctions.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::gl {

// A default-block ("loose") uniform of native GLSL, set with glProgramUniform*.
struct LooseUniform {
  GLint location = -1;
  GLenum type = 0;
  // offset 0, tightly packed (matrix_stride = vecsize * 4, column registers), the way
  // glProgramUniform*v reads its array, so pack_uniform_block produces the call's data.
  UniformMember member;
};

struct GlProgramInterface {
  std::vector<UniformBlock> uniform_blocks;   // binding = the GL uniform buffer binding point
  std::vector<LooseUniform> loose_uniforms;
  std::vector<StageInput> inputs;             // vertex attributes, by location
  std::vector<SamplerBinding> samplers;       // binding = the texture unit; set is always 0
};

enum class BlockBindings {
  keep,             // report what the program has
  // GLSL without layout(binding) leaves every block at binding 0 and every sampler at
  // texture unit 0: give each block its own binding and each sampler its own unit.
  assign_distinct,
};

Result<GlProgramInterface> introspect_gl_program(const GlFunctions& gl, GLuint program, BlockBindings bindings);

// The union of the vertex_gl and fragment_gl reflections; a binding used by two
// different blocks, or a texture unit by two different samplers, is an error (GL has
// one namespace of each for all stages). A sampler both stages declare is one sampler.
Result<GlProgramInterface> interface_from_reflection(const CompiledProgram& program);

// SPIRV-Cross GLSL must reproduce the SPIR-V's offsets or the reflection-packed bytes land
// in the wrong members. Compares GL's view of the linked cross GLSL with the reflection,
// member by member (by binding and name), and names the first disagreement. Samplers
// are compared by texture unit and dimensions only: SPIRV-Cross may rename them, and
// the units (its layout(binding)) are what the textures are bound to.
Result<void> check_cross_glsl_layout(const GlProgramInterface& from_gl, const GlProgramInterface& reflected);

}  // namespace shaderbed::gl
