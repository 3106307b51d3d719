#include "compile/GlslDialect.h"

#include "compile/GlslProfile.h"
#include "compile/GlslVaryings.h"
#include "compile/LegacyGlsl.h"

namespace shaderbed {

Result<PreparedGlsl> prepare_glsl_program(const ProgramSource& program) {
  PreparedGlsl out{.program = program, .legacy_names = {}, .compatibility = false, .native_skip_reason = {}};
  for (ShaderSource* stage : {&out.program.vertex, &out.program.fragment}) {
    if (auto construct = vulkan_only_construct(stage->text); construct && out.native_skip_reason.empty())
      out.native_skip_reason = "Vulkan GLSL (" + *construct + " of " + stage->path +
                               ") is not desktop GL GLSL: the native GL path does not apply";
    const GlslVersion version = glsl_version(stage->text);
    if (!is_legacy_glsl(version)) continue;
    out.compatibility = true;
    auto translated = translate_legacy_glsl(*stage, version);
    if (!translated) return std::unexpected(translated.error());
    stage->text = std::move(translated->text);
    out.legacy_names.insert(translated->legacy_names.begin(), translated->legacy_names.end());
  }
  auto varyings = assign_varying_locations(out.program.vertex, out.program.fragment);
  if (!varyings) return std::unexpected(varyings.error());
  out.program.vertex.text = std::move(varyings->vertex);
  out.program.fragment.text = std::move(varyings->fragment);
  return out;
}

void restore_legacy_names(Reflection& reflection, const std::map<std::string, std::string>& legacy_names) {
  const auto restore = [&](std::string& name) {
    if (auto it = legacy_names.find(name); it != legacy_names.end()) name = it->second;
  };
  for (UniformBlock& block : reflection.uniform_blocks)
    for (UniformMember& member : block.members) restore(member.name);
  for (StageInput& input : reflection.inputs) restore(input.name);
  for (SamplerBinding& sampler : reflection.samplers) restore(sampler.name);
}

}  // namespace shaderbed
