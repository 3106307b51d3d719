#pragma once
// What `shaderbed init` reads from a shader's text where the reflection is silent: a
// global's semantic, register and the space its annotation or comment names, the order
// mul() takes a matrix in, which GLSL stage a file is, and which HLSL/Cg functions are
// entry points (their outputs carry POSITION or COLOR). Cheap scans of the author's text,
// not a parser: a guess they miss becomes a TODO or a comment, never a wrong error.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "author/BindingGuess.h"
#include "compile/ShaderModule.h"

namespace shaderbed {

// `float4x4 g_mWorld : WORLD;` -> "WORLD"; "" when the declaration has none.
std::string declared_semantic(std::string_view text, std::string_view name);

// `matrix Transform : register(c0);` -> 0; -1 when it has no constant register.
int declared_register(std::string_view text, std::string_view name);

// The space an annotation (`string Space = "World";`) or the declaration's comment
// ("// world space") names.
SpaceHint declared_space(std::string_view text, std::string_view name);

// What the declaration's trailing comment says its components mean:
// `float4 SpecularColor; // rgb = colour, w = specular power` -> {{"rgb", "colour"}, {"w", "specular power"}}.
std::vector<std::pair<std::string, std::string>> component_meanings(std::string_view text, std::string_view name);

// mul(M, v) -> column_vector, mul(v, M) -> row_vector (casts such as (float3x3)M
// allowed); the first mul() naming the matrix decides; nullopt when none does.
std::optional<MatrixLayout> mul_order(std::string_view text, std::string_view name);

// A GLSL file's stage by its text: a file that writes gl_Position is a vertex shader.
Stage glsl_stage_of(std::string_view text);

// HLSL/Cg functions whose outputs (return value, its struct's members, out parameters)
// carry a vertex position (POSITION, SV_Position, HPOS) or a colour (COLOR, SV_Target).
struct EntryCandidate {
  std::string function;
  Stage stage = Stage::vertex;
  int line = 0;
};
// Errors when the text is not something the effect layer reads (compile/EffectFile.h).
Result<std::vector<EntryCandidate>> entry_candidates(std::string_view text, const std::string& path);

}  // namespace shaderbed
