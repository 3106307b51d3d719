#pragma once
// What compile_program does to a GLSL program before glslang sees it, for the SPIR-V
// paths (the native GL path always gets the author's source):
//  - legacy GLSL (GlslProfile.h) goes through the dialect layer (LegacyGlsl.h);
//  - varyings without locations get matching ones in both stages (GlslVaryings.h);
//  - GLSL ES 3.00 is compiled as 3.10 ES, the first ES version glslang takes for SPIR-V
//    (3.10 adds to 3.00; it takes every 3.00 shader), on the #version line it had.
// And what the GL backend needs to know about the author's source: whether Mesa must
// compile it in a compatibility context, whether the native path does not apply, and
// the text it compiles: the author's, with `#version 100` put first for an unversioned
// WebGL 1 shader (Mesa would read it as desktop 1.10, which has no precision statements).
#include <map>
#include <string>

#include "compile/Compiler.h"
#include "core/Error.h"

namespace shaderbed {

struct PreparedGlsl {
  ProgramSource program;                            // what glslang compiles
  std::map<std::string, std::string> legacy_names;  // dialect name -> the name reflected
  bool compatibility = false;                       // native GLSL needs a compatibility context
  std::string native_skip_reason;                   // "": the native GL path applies
  std::string native_vertex, native_fragment;       // what the native GL path compiles
  // An ES shader that declares mediump or lowp: Mesa's GLSL compiler computes it in 16-bit
  // floats on llvmpipe (checked: a mediump Lambert differs by 1e-3 on gl/glsl only). The
  // SPIR-V paths carry it as RelaxedPrecision, which lavapipe and Mesa's ARB_gl_spirv
  // ignore, and SPIRV-Cross's desktop GLSL drops it.
  bool native_reduced_precision = false;
};

Result<PreparedGlsl> prepare_glsl_program(const ProgramSource& program);

// Renames what the dialect declared (uniform members, vertex inputs, samplers) to the
// names the author wrote, so bindings and messages use those.
void restore_legacy_names(Reflection& reflection, const std::map<std::string, std::string>& legacy_names);

}  // namespace shaderbed
