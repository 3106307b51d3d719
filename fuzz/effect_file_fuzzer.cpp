// libFuzzer target: the DX9 effect-file layer (compile/EffectFile.h, EffectStates.h and the
// effect front end that picks a technique and pass): text in, HLSL text and states out,
// before glslang.
#include <cstddef>
#include <cstdint>

#include "FuzzSupport.h"
#include "compile/EffectFile.h"
#include "compile/EffectFrontEnd.h"
#include "compile/EffectStates.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  const std::string_view text = fuzz::as_text(data, size);
  (void)is_effect_file("fuzz.hlsl", text);
  auto effect = parse_effect(text, "fuzz.fx");
  if (!effect) {
    (void)effect.error().to_string();
    return 0;
  }
  // Every pass's states, not only the first technique's.
  for (const EffectTechnique& technique : effect->techniques)
    for (const EffectPass& pass : technique.passes) (void)interpret_pass(pass, "fuzz.fx");
  for (const Stage stage : {Stage::vertex, Stage::fragment}) {
    const ShaderSource file{.stage = stage, .path = "fuzz.fx", .text = std::string(text), .entry_point = "main"};
    (void)prepare_effect_stage(file, EffectChoice{});
  }
  return 0;
}
