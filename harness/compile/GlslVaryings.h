#pragma once
// Varying locations for GLSL written for GL, where the linker matches a vertex output
// and a fragment input by name. SPIR-V matches them by location, and glslang numbers
// each stage in the order it meets them, so a pair that declares its varyings in
// different orders (or a vertex shader with one more) would be linked wrongly. Every
// top-level vertex `out` and fragment `in` without layout(location) gets one: vertex
// outputs in declaration order (after the explicit ones), each fragment input the
// location of the vertex output of its name (interface blocks by block name). Sources
// whose varyings all have locations come back unchanged; lines never move.
#include <utility>

#include "compile/Compiler.h"
#include "core/Error.h"

namespace shaderbed {

struct VaryingSources {
  std::string vertex;
  std::string fragment;
};

Result<VaryingSources> assign_varying_locations(const ShaderSource& vertex, const ShaderSource& fragment);

}  // namespace shaderbed
