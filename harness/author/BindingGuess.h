#pragma once
// What `shaderbed init` guesses a shader's uniform or vertex input is, from what the
// shader says about it: the uniform's name ("mWVP", "u_model", "lightPos",
// "gl_LightSource[0].position"), its effect semantic (WORLDVIEWPROJECTION), its HLSL
// register (the book's layout: c0 transform, c4 light vector, c5 eye position, c6 light
// position), its type (a mat3 "normalMatrix" is the normal matrix), the mul() order its
// source uses, and the comment or annotation on its declaration ("// world space").
// Every guess carries the sentence that explains it; a uniform it cannot place is a TODO
// with a commented-out placeholder of the right size. Pure: no files, no compiler.
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "compile/ShaderModule.h"
#include "scene/CaseFile.h"

namespace shaderbed {

// Which space a shader's lighting vectors and positions are in, when the shader says.
enum class SpaceHint { none, object, world, view };

// One uniform as the reflection and the source text describe it.
struct UniformFacts {
  std::string name;             // as reflected (the key of [bindings.<language>])
  bool is_float = true;
  uint32_t vecsize = 1;         // rows of a matrix, components of a vector
  uint32_t columns = 1;         // > 1: a matrix
  uint32_t array_size = 0;      // 0: not an array
  std::string semantic;         // an HLSL/effect semantic on the declaration, "" = none
  int hlsl_register = -1;       // register(cN) on the declaration, -1 = none
  SpaceHint declared_space = SpaceHint::none;   // from its annotation or comment
  // HLSL/Cg matrices: the order mul() takes this matrix in, when the source shows it
  // (mul(v, M): row_vector); nullopt when no mul() names it.
  std::optional<MatrixLayout> mul_order;
  // What the declaration's comment says its components mean: `// rgb = colour, w = specular
  // power` -> {{"rgb", "colour"}, {"w", "specular power"}}.
  std::vector<std::pair<std::string, std::string>> component_meanings;
  bool read = true;             // some stage's compiled code reads it (else it needs no binding)
};

// What holds for the whole shader of one language.
struct GuessContext {
  Language language = Language::hlsl;
  // The shader has a world (model) matrix uniform, so positions it computes are likely in
  // world space: lighting vectors without a hint then take the _world quantities.
  bool has_world_matrix = false;
};

// A case parameter a guess introduces, with a default that renders something sensible.
struct ParameterGuess {
  std::string name;             // "diffuse", "specular", "power"
  std::vector<double> value;
  std::string reason;
};

struct UniformGuess {
  std::vector<BindingSource> sources;   // empty: no guess, a TODO
  MatrixLayout layout = MatrixLayout::column_vector;
  std::string reason;                   // why, for the line's comment (or the TODO's text)
  std::vector<ParameterGuess> parameters;
  // The uniform takes its value without a binding (a legacy GL matrix the scene fills).
  bool bound_by_default = false;
  std::vector<double> placeholder;      // TODO: zeros of the uniform's size, for the commented-out line
  // A guess the shader's text does not settle (a matrix no mul() names, a float4 light that
  // may be a position or a direction, a w nobody explains) says what it is unsure of and what
  // it would bind instead; `shaderbed init` tries that when its own run shows a blank
  // original or a failing port. "" = the text settles it.
  std::string doubt;                    // "row or column vectors", "position or direction"
  std::vector<UniformGuess> alternatives;
  // Guesses that switch together: every matrix of a shader whose mul()s it cannot see
  // (a shader writes them all one way); "" = this uniform alone.
  std::string doubt_group;
  bool todo() const { return sources.empty() && !bound_by_default; }
  bool unsure() const { return !doubt.empty() && !alternatives.empty(); }
};

UniformGuess guess_uniform(const UniformFacts& uniform, const GuessContext& context);

// The words a name is made of, lower case, prefixes (g_, u_, m, Hungarian f/v/m) dropped
// and glued words split ("mWVP" -> {wvp}, "g_mWorldViewProjection" -> {world, view,
// projection}, "gl_LightSource[0].position" -> {gl, light, source, 0, position}).
std::vector<std::string> name_words(std::string_view name);

// A uniform's type as the language writes it: "float3", "float4x4", "vec3", "mat3", "int".
std::string type_text(const UniformFacts& uniform, Language language);

// The mesh attribute a vertex input named so most likely is ("position", "normal",
// "tangent", "texcoord", "color"), with why; nullopt when the name says nothing.
struct AttributeGuess {
  std::string attribute;
  std::string reason;
};
std::optional<AttributeGuess> guess_attribute(std::string_view input_name);

}  // namespace shaderbed
