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

Result<std::vector<uint32_t>> optimize_spirv(const std::vector<uint32_t>& spirv, Target target, OptimizeLevel level);

}  // namespace shaderbed
