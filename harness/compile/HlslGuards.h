#pragma once
// HLSL constructs that crash glslang 12 in-process: refused with one error at their line
// before glslang sees them, so bad input never takes the process down.
#include "compile/Compiler.h"

namespace shaderbed {

Result<void> reject_glslang_crashers(const ShaderSource& source);

}  // namespace shaderbed
