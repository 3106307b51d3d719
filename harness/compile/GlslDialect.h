#pragma once
// What compile_program does to a GLSL program before glslang sees it, for the SPIR-V
// paths (the native GL path always gets the author's source):
//  - legacy GLSL (GlslProfile.h) goes through the dialect layer (LegacyGlsl.h);
//  - varyings without locations get matching ones in both stages (GlslVaryings.h).
// And what the GL backend needs to know about the author's source: whether Mesa must
// compile it in a compatibility context, or whether the native path does not apply.
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
};

Result<PreparedGlsl> prepare_glsl_program(const ProgramSource& program);

// Renames what the dialect declared (uniform members, vertex inputs, samplers) to the
// names the author wrote, so bindings and messages use those.
void restore_legacy_names(Reflection& reflection, const std::map<std::string, std::string>& legacy_names);

}  // namespace shaderbed
