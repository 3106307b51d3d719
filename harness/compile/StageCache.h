#pragma once
// compile_stage() remembered for the life of the process, keyed by everything it reads:
// language, stage, target, entry point, path and the exact source text. Many programs share
// a stage (every per-pixel variant's setup vertex shader; a sweep recompiles the same
// program at every point), and glslang + spirv-opt + spirv-val are most of a compile.
// Files a source #includes are read at their first compile and not re-checked after.
// Thread-safe: run's workers share it.
#include "compile/Compiler.h"

namespace shaderbed {

Result<ShaderModule> compile_stage_cached(Language language, const ShaderSource& source, Target target);

}  // namespace shaderbed
