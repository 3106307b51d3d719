#pragma once
// SPIRV-Cross: SPIR-V back to GLSL 450 core for the GL driver's own compiler. This is
// the path that isolates cross-compiler faults from front-end and driver faults.
#include <cstdint>
#include <string>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

Result<std::string> spirv_to_glsl(const std::vector<uint32_t>& spirv, Stage stage);

}  // namespace shaderbed
