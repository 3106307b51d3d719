#pragma once
// What a compiled program leaves for reports: SPIR-V disassembly and SPIRV-Cross GLSL
// next to the renders, and a hash of the SPIR-V handed to drivers, so two runs (or two
// toolchains) can be told apart by what the drivers actually saw.
#include <string>

#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

std::string spirv_hash(const std::vector<uint32_t>& spirv);   // FNV-1a 64, hex

// Writes <dir>/<language>.{vert,frag}.spvasm and .cross.glsl; fills the artefact paths.
Result<void> write_program_artefacts(const std::string& dir, const CompiledProgram& program, CellArtefacts& out);

}  // namespace shaderbed
