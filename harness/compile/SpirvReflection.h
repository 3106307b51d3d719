#pragma once
// Reads what a SPIR-V module asks to be bound: uniform blocks with member offsets,
// vertex inputs with locations (and HLSL semantics), samplers.
#include <cstdint>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

Result<Reflection> reflect_spirv(const std::vector<uint32_t>& spirv, Language language, Stage stage);

}  // namespace shaderbed
