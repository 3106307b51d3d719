#pragma once
// The compile caches compile_program() goes through, in two layers:
//  - in memory, for the life of the process: compile_stage() results keyed by everything
//    it reads (language, stage, target, entry point, path and the exact source text).
//    Many programs share a stage (every per-pixel variant's setup vertex shader; a sweep
//    recompiles the same program at every point). Files a source #includes are read at
//    their first compile and not re-checked after. Failures are remembered too.
//  - on disk, between processes (CompileCache.h), when the cache settings have it on
//    (core/CacheSettings.h; `--no-compile-cache` turns it off): successes only, includes
//    re-checked on every hit. SPIRV-Cross GLSL has only this layer.
// glslang + spirv-opt + spirv-val are most of a compile, and glslang's first compile in a
// process builds its built-in tables (~210 ms): a warm process starts neither.
// Thread-safe: run's workers share them.
#include "compile/Compiler.h"

namespace shaderbed {

Result<ShaderModule> compile_stage_cached(Language language, const ShaderSource& source, Target target);

// spirv_to_glsl() (CrossGlsl.h) through the disk cache.
Result<std::string> spirv_to_glsl_cached(const std::vector<uint32_t>& spirv, Stage stage);

}  // namespace shaderbed
