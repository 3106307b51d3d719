#pragma once
// A case's preprocessor defines (ShaderSource::defines) as each front end takes them:
// HLSL, Cg and effects in glslang's preamble (before line 1, so messages keep the
// author's line numbers); GLSL, whose #version must come first, in the text right after
// #version with a #line that restores the numbering, so Mesa's own compiler (the native
// GL path), the GLSL dialect layer and glslang all see the same defined source.
#include <string>
#include <vector>

#include "compile/Compiler.h"

namespace shaderbed {

// "#define NAME VALUE\n" per define, in order.
std::string define_lines(const std::vector<Define>& defines);

// The GLSL text with the defines after its #version line (or first, with none); the text
// itself when there are none.
std::string glsl_with_defines(const std::string& text, const std::vector<Define>& defines);

}  // namespace shaderbed
