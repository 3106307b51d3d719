#pragma once
// The DX9 effect front end: an effect file (EffectFile.h) becomes, per stage, the plain
// DX9-style HLSL glslang compiles, entered where the chosen technique and pass say
// (`VertexShader = compile vs_2_0 VS();`), plus the pass's render states and the
// sampler_state settings (EffectStates.h) the draw needs.
//
// `compile ps_2_0 PS(true, 4)` binds values to PS's uniform parameters, in order: a
// wrapper entry is appended (after a `#line` naming the compile statement's line, so its
// errors point there) that takes PS's other parameters and passes the arguments in as
// constants. A uniform parameter left without an argument and without a default is an
// error, as fxc makes it.
//
// Profiles: vs_/ps_ 2_0 and 3_0 (and 1_x) compile in glslang's DX9 HLSL mode, as every
// HLSL shader here does; 4_0 and up compile in the same mode, which also reads SM4+
// syntax (Texture2D, SamplerState, cbuffer).
#include <map>
#include <string>
#include <vector>

#include "pipeline/RenderState.h"
#include "pipeline/SamplerSettings.h"
#include "compile/Compiler.h"
#include "compile/EffectFile.h"

namespace shaderbed {

struct EffectStage {
  ShaderSource source;     // the HLSL glslang compiles; same path, entry point set
  std::string technique;   // the chosen ones, as named in the file
  std::string pass;
  std::string profile;     // e.g. "ps_2_0"
  RenderState render_state;
  std::map<std::string, SamplerSettings> samplers;  // by sampler name
  std::map<std::string, std::string> sampler_textures;   // sampler -> the texture its sampler_state names
  std::map<std::string, std::vector<double>> initial_values;   // by global name
  std::vector<EffectNote> notes;
};

// One stage of a program from an effect file. A technique or pass the case names that the
// effect lacks is an error at the case file's line (choice.named_in), listing what exists.
Result<EffectStage> prepare_effect_stage(const ShaderSource& file, const EffectChoice& choice);

// Rewrites every stage of `program` whose file is an effect; the others stay as they are.
// The render state, sampler settings, the textures the samplers name and the globals'
// initial values come from the effect (the vertex stage's render state if both stages
// name one), written to `compiled` (render_state, sampler_settings,
// effect_sampler_textures, uniform_defaults).
Result<ProgramSource> prepare_effect_program(const ProgramSource& program, CompiledProgram& compiled);

}  // namespace shaderbed
