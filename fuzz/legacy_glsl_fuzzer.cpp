// libFuzzer target: the GLSL dialect layer before glslang (compile/LegacyGlsl.h,
// GlslDialect.h: the version scan, the legacy rewrite and the varying locations) on a
// vertex and a fragment stage. glslang itself is not fuzzed here.
#include <cstddef>
#include <cstdint>

#include "FuzzSupport.h"
#include "compile/GlslDialect.h"
#include "compile/GlslProfile.h"
#include "compile/LegacyGlsl.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  const fuzz::StagePair stages = fuzz::stage_pair(fuzz::as_text(data, size));
  ProgramSource program{.language = Language::glsl,
                        .vertex = {.stage = Stage::vertex, .path = "fuzz.vert", .text = std::string(stages.vertex)},
                        .fragment = {.stage = Stage::fragment, .path = "fuzz.frag", .text = std::string(stages.fragment)}};
  for (const ShaderSource* stage : {&program.vertex, &program.fragment}) {
    (void)needs_relaxed_vulkan_rules(stage->text);
    (void)vulkan_only_construct(stage->text);
  }
  auto prepared = prepare_glsl_program(program);
  if (!prepared) {
    (void)prepared.error().to_string();
    return 0;
  }
  for (const auto& [name, legacy_name] : prepared->legacy_names) (void)legacy_glsl_default_binding(legacy_name);
  return 0;
}
