#pragma once
// The DX9 effect file (.fx) parser. glslang reads HLSL functions and globals but none of
// the effect syntax around them (`texture t;`, `sampler s = sampler_state {...};`,
// `technique T { pass P { ... } }`, annotations `< ... >`: each is "'declaration' :
// Expected"). parse_effect() finds that syntax, records it, and blanks it out of the
// text, keeping every line break where it was, so glslang compiles what is left and its
// errors keep pointing at the author's lines.
//
// Read from the author's file as written (no preprocessing, so a warm run starts no
// compiler): `#include`s and macros stay for glslang; a macro inside a technique block
// is not expanded. What an #if drops is not read (EffectConditionals.h): a D3D10
// `RasterizerState` or `technique10` in the branch not taken is not judged.
//
// Recorded: techniques (technique, technique10, technique11) and their passes, with each
// pass's state assignments as written (interpreted for the chosen pass only, by
// EffectStates.h: an unused fixed-function fallback technique is not an error);
// `texture`/`texture2D`/`textureCUBE`/... declarations; samplers declared with
// `= sampler_state { ... }` (their states are checked here: an unknown one is an error at
// its line) which become plain `sampler2D`/`samplerCUBE`/... declarations; top-level
// functions with their parameters (for `compile` arguments). Dropped: annotations, `string`
// globals, the `shared` qualifier. Kept: semantics and initialisers on globals (glslang
// accepts both; an initialised global is still a uniform, which the case binds or which
// takes its initial value, as D3DX sets it).
// Refused with the construct and line: `VertexShader`/`PixelShader` variables and `asm`
// blocks, state blocks other than sampler_state (`stateblock`, `BlendState` ...).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/SamplerSettings.h"
#include "core/Error.h"

namespace shaderbed {

// Something the effect layer did on the author's behalf, with where and why.
struct EffectNote {
  int line = 0;
  std::string text;
};

// `Name = value;` or `Name[index] = value;` inside a pass, as written.
struct EffectAssignment {
  std::string name;
  int index = -1;          // -1: no [index]
  std::string value;       // the value's tokens, single-space separated
  std::vector<std::string> value_tokens;
  int line = 0;
};

struct EffectPass {
  std::string name;        // "" for an unnamed pass (named by its index in messages)
  int line = 0;
  std::vector<EffectAssignment> states;
};

struct EffectTechnique {
  std::string name;
  int line = 0;
  std::vector<EffectPass> passes;
};

struct EffectTexture {
  std::string name;
  std::string type;        // as written: texture, texture2D, textureCUBE, ...
  int line = 0;
};

struct EffectSampler {
  std::string name;
  std::string type;        // as declared in the HLSL glslang reads: sampler2D, samplerCUBE, ...
  std::string texture;     // the `Texture = <t>` it samples ("" when the block names none)
  SamplerSettings settings;
  int line = 0;
};

struct EffectParameter {
  std::string text;        // as written, e.g. "float4 pos : POSITION", "uniform bool flip"
  std::string name;
  bool is_uniform = false;
  std::string default_value;  // "= value" as written, without the '='; "" = none
};

struct EffectFunction {
  std::string name;
  std::string return_type;      // as written, e.g. "float4", "VS_OUTPUT"
  std::string return_semantic;  // e.g. "COLOR0"; "" = none
  std::vector<EffectParameter> parameters;
  int line = 0;
};

// A global's initial value (`float3 g_vF0 = {0.04, 0.04, 0.04};`, `float g_f = 0.5f;`):
// what the parameter holds until the application sets it, so what the case binds it to
// when it binds nothing. Scalars and vectors of numbers only; a scalar fills a vector.
struct EffectInitialValue {
  std::vector<double> values;
  int line = 0;
};

struct EffectFile {
  std::string path;
  std::string hlsl;        // the text glslang compiles: effect syntax blanked, same lines
  std::vector<EffectTechnique> techniques;
  std::vector<EffectTexture> textures;
  std::vector<EffectSampler> samplers;
  std::vector<EffectFunction> functions;
  std::map<std::string, EffectInitialValue> initial_values;   // by global name
  std::vector<EffectNote> notes;

  const EffectFunction* function(std::string_view name) const;
};

// Whether a shader is a DX9 effect: a .fx/.fxh file, or one whose text declares a
// technique block.
bool is_effect_file(const std::string& path, std::string_view text);

// Errors carry `path` and the line of the construct.
Result<EffectFile> parse_effect(std::string_view text, const std::string& path);

}  // namespace shaderbed
