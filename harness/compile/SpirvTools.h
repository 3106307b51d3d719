#pragma once
// SPIRV-Tools: validation with the target's environment, optimisation, disassembly.
#include <cstdint>
#include <string>
#include <vector>

#include "compile/Compiler.h"

namespace shaderbed {

enum class OptimizeLevel { performance, size };   // spirv-opt -O / -Os

// spirv-val; the error names the source file and the validator's message.
Result<void> validate_spirv(const std::vector<uint32_t>& spirv, Target target, const std::string& source_path);

// Removes what only reflection needs (HLSL semantic decorations and their
// SPV_GOOGLE_hlsl_functionality1 extension), which Vulkan drivers are not asked to enable.
Result<std::vector<uint32_t>> strip_reflection_info(const std::vector<uint32_t>& spirv, Target target);

Result<std::vector<uint32_t>> optimize_spirv(const std::vector<uint32_t>& spirv, Target target, OptimizeLevel level);

}  // namespace shaderbed
