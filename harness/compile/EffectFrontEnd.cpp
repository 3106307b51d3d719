#include "compile/EffectFrontEnd.h"

#include "compile/EffectStates.h"

namespace shaderbed {
namespace {

std::string pass_label(const EffectPass& pass, std::size_t index) {
  return pass.name.empty() ? "#" + std::to_string(index) : pass.name;
}

Error choice_error(const EffectChoice& choice, const std::string& effect_path, std::string message) {
  if (choice.named_in.empty())
    return Error{.message = std::move(message), .file = effect_path, .stage = ErrorStage::compile};
  return Error{.message = std::move(message) + " (in " + effect_path + ")", .file = choice.named_in,
               .line = choice.line, .stage = ErrorStage::case_file};
}

Result<const EffectTechnique*> find_technique(const EffectFile& effect, const EffectChoice& choice) {
  if (choice.technique.empty()) return &effect.techniques.front();
  std::string names;
  for (const EffectTechnique& t : effect.techniques) {
    if (t.name == choice.technique) return &t;
    names += (names.empty() ? "" : ", ") + t.name;
  }
  return std::unexpected(
      choice_error(choice, effect.path, "no technique '" + choice.technique + "' in the effect (it has: " + names + ")"));
}

Result<const EffectPass*> find_pass(const EffectFile& effect, const EffectTechnique& technique,
                                    const EffectChoice& choice) {
  if (choice.pass.empty()) return &technique.passes.front();
  std::string names;
  for (std::size_t i = 0; i < technique.passes.size(); ++i) {
    if (technique.passes[i].name == choice.pass) return &technique.passes[i];
    names += (names.empty() ? "" : ", ") + pass_label(technique.passes[i], i);
  }
  return std::unexpected(choice_error(choice, effect.path, "no pass '" + choice.pass + "' in technique '" +
                                                               technique.name + "' (it has: " + names + ")"));
}

Error at_compile(const EffectShaderCompile& c, const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .line = c.line, .stage = ErrorStage::compile};
}

// The entry glslang is given: the function itself, or a wrapper passing the `compile`
// statement's arguments to its uniform parameters (appended to `hlsl`).
Result<std::string> entry_for(const EffectFile& effect, const EffectShaderCompile& c, std::string& hlsl) {
  const EffectFunction* f = effect.function(c.function);
  if (!f)
    return std::unexpected(at_compile(c, effect.path, "compile " + c.profile + " " + c.function +
                                                          "(...) names a function the effect does not define"));
  std::size_t uniforms = 0;
  for (const EffectParameter& p : f->parameters) uniforms += p.is_uniform;
  if (c.arguments.size() > uniforms)
    return std::unexpected(at_compile(c, effect.path, "compile " + c.profile + " " + c.function + " passes " +
                                                          std::to_string(c.arguments.size()) + " arguments, but " +
                                                          c.function + " has " + std::to_string(uniforms) +
                                                          " uniform parameters (line " + std::to_string(f->line) + ")"));
  if (uniforms == 0) return c.function;

  std::string wrapper_params, call_args;
  std::size_t next_argument = 0;
  for (const EffectParameter& p : f->parameters) {
    std::string value;
    if (p.is_uniform) {
      if (next_argument < c.arguments.size()) {
        value = c.arguments[next_argument++];
      } else if (!p.default_value.empty()) {
        value = p.default_value;
      } else {
        return std::unexpected(at_compile(c, effect.path, "uniform parameter '" + p.name + "' of " + c.function +
                                                              " gets no value from `compile " + c.profile + " " +
                                                              c.function + "(...)` and has no default"));
      }
      value = "(" + value + ")";
    } else {
      wrapper_params += (wrapper_params.empty() ? "" : ", ") + p.text;
      value = p.name;
    }
    call_args += (call_args.empty() ? "" : ", ") + value;
  }
  const std::string name = "shaderbed_" + c.function + "_compiled";
  const bool returns = f->return_type != "void";
  hlsl += "\n#line " + std::to_string(c.line) + "\n";
  hlsl += f->return_type + " " + name + "(" + wrapper_params + ")" +
          (f->return_semantic.empty() ? "" : " : " + f->return_semantic) + " { " + (returns ? "return " : "") +
          c.function + "(" + call_args + "); }\n";
  return name;
}

}  // namespace

Result<EffectStage> prepare_effect_stage(const ShaderSource& file, const EffectChoice& choice) {
  auto effect = parse_effect(file.text, file.path);
  if (!effect) return std::unexpected(effect.error());
  auto technique = find_technique(*effect, choice);
  if (!technique) return std::unexpected(technique.error());
  auto pass = find_pass(*effect, **technique, choice);
  if (!pass) return std::unexpected(pass.error());
  auto states = interpret_pass(**pass, file.path);
  if (!states) return std::unexpected(states.error());

  const bool vertex = file.stage == Stage::vertex;
  const auto& compiled = vertex ? states->vertex : states->pixel;
  if (!compiled)
    return std::unexpected(Error{.message = "pass '" + (*pass)->name + "' of technique '" + (*technique)->name +
                                            "' sets no " + (vertex ? "VertexShader" : "PixelShader") +
                                            " (shaderbed has no fixed-function pipeline)",
                                 .file = file.path,
                                 .line = (*pass)->line,
                                 .stage = ErrorStage::compile});
  EffectStage out;
  out.technique = (*technique)->name;
  out.pass = (*pass)->name;
  out.profile = compiled->profile;
  out.render_state = states->render_state;
  out.notes = std::move(effect->notes);
  out.notes.insert(out.notes.end(), states->notes.begin(), states->notes.end());
  for (const EffectSampler& s : effect->samplers) {
    out.samplers[s.name] = s.settings;
    if (!s.texture.empty()) out.sampler_textures[s.name] = s.texture;
  }
  for (const auto& [name, initial] : effect->initial_values) out.initial_values[name] = initial.values;
  std::string hlsl = effect->hlsl;
  auto entry = entry_for(*effect, *compiled, hlsl);
  if (!entry) return std::unexpected(entry.error());
  out.source = ShaderSource{.stage = file.stage, .path = file.path, .text = std::move(hlsl), .entry_point = *entry,
                            .defines = file.defines, .include_dirs = file.include_dirs};
  return out;
}

Result<ProgramSource> prepare_effect_program(const ProgramSource& program, CompiledProgram& compiled) {
  ProgramSource out = program;
  bool state_taken = false;
  for (ShaderSource* stage : {&out.vertex, &out.fragment}) {
    if (!is_effect_file(stage->path, stage->text)) continue;
    auto prepared = prepare_effect_stage(*stage, program.effect);
    if (!prepared) return std::unexpected(prepared.error());
    if (!state_taken) {
      compiled.render_state = prepared->render_state;
      state_taken = true;
    }
    compiled.sampler_settings.insert(prepared->samplers.begin(), prepared->samplers.end());
    compiled.effect_sampler_textures.insert(prepared->sampler_textures.begin(), prepared->sampler_textures.end());
    compiled.uniform_defaults.insert(prepared->initial_values.begin(), prepared->initial_values.end());
    *stage = std::move(prepared->source);
  }
  if (!state_taken && (!program.effect.technique.empty() || !program.effect.pass.empty()))
    return std::unexpected(choice_error(program.effect, program.vertex.path,
                                        "the case picks a technique or pass, but neither shader is a DX9 effect "
                                        "(no technique block)"));
  return out;
}

}  // namespace shaderbed
