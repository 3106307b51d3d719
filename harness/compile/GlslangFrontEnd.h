#pragma once
// glslang front end: GLSL or DX9-style HLSL source to unvalidated SPIR-V.
#include <cstdint>
#include <vector>

#include "compile/Compiler.h"

namespace shaderbed {

// Binding numbers a stage's auto-mapped resources start from. GL has a single binding
// namespace for all stages, so HLSL vertex and pixel $Global blocks must not collide.
constexpr unsigned kFragmentBindingBase = 8;

Result<std::vector<uint32_t>> glslang_to_spirv(Language language, const ShaderSource& source, Target target);

}  // namespace shaderbed
