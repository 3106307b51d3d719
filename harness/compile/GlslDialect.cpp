#include "compile/GlslDialect.h"

#include <algorithm>

#include "compile/GlslProfile.h"
#include "compile/GlslVaryings.h"
#include "compile/LegacyGlsl.h"

namespace shaderbed {
namespace {

// `text` with its #version directive (on `version.line`) replaced by `directive`, every
// other line where it was.
std::string with_version_directive(const std::string& text, const GlslVersion& version, const std::string& directive) {
  size_t begin = 0;
  for (int line = 1; line < version.line && begin != std::string::npos; ++line) {
    begin = text.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  if (begin == std::string::npos) return text;
  const size_t end = std::min(text.find('\n', begin), text.size());
  return text.substr(0, begin) + directive + text.substr(end);
}

}  // namespace

Result<PreparedGlsl> prepare_glsl_program(const ProgramSource& program) {
  PreparedGlsl out{.program = program, .legacy_names = {}, .compatibility = false, .native_skip_reason = {},
                   .native_vertex = program.vertex.text, .native_fragment = program.fragment.text};
  for (ShaderSource* stage : {&out.program.vertex, &out.program.fragment}) {
    std::string& native = stage == &out.program.vertex ? out.native_vertex : out.native_fragment;
    const GlslVersion version = glsl_version(stage->text);
    if (is_glsl_es(version, stage->text) && declares_reduced_precision(stage->text))
      out.native_reduced_precision = true;
    // #line 1: the author's first line is still line 1 in Mesa's messages.
    if (is_unversioned_glsl_es(version, stage->text)) native = "#version 100\n#line 1\n" + native;
    if (version.es && version.number < 310)
      stage->text = with_version_directive(stage->text, version, "#version 310 es");
    if (auto construct = vulkan_only_construct(stage->text); construct && out.native_skip_reason.empty())
      out.native_skip_reason = "Vulkan GLSL (" + *construct + " of " + stage->path +
                               ") is not desktop GL GLSL: the native GL path does not apply";
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
