#pragma once
// Default-block uniforms (samplers) of OpenGL-target SPIR-V carry explicit locations,
// and GL has one location namespace per program: a vertex and a fragment uniform at one
// location are linked as one uniform. glslang numbers each stage from 0, so a vertex
// sampler and a fragment sampler can land on the same location. Mesa then silently
// binds one stage's sampler to the other's unit (SPIR-V path) or refuses to link the
// SPIRV-Cross GLSL. This check turns both into one clear error before the driver runs.
#include <cstdint>
#include <string>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::gl {

struct SpirvUniformLocation {
  uint32_t location = 0;
  std::string name;           // OpName, may be empty
  int64_t binding = -1;       // -1: no Binding decoration
};

// The UniformConstant variables of a module that have a Location decoration.
std::vector<SpirvUniformLocation> spirv_uniform_locations(const std::vector<uint32_t>& spirv);

// Error when vertex_gl and fragment_gl declare different uniforms (by name or binding)
// at the same location.
Result<void> check_uniform_locations_across_stages(const CompiledProgram& program);

}  // namespace shaderbed::gl
