// libFuzzer target: the Cg dialect layer (compile/CgDialect.h), the text passes that run
// before glslang: prepare_cg_file on the input as read, then translate_cg on the result as
// if it were glslang's preprocessed output. glslang itself is not fuzzed here.
#include <cstddef>
#include <cstdint>

#include "FuzzSupport.h"
#include "compile/CgDialect.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  const fuzz::ShaderInput in = fuzz::shader_input(fuzz::as_text(data, size));
  auto prepared = prepare_cg_file(in.text, "fuzz.cg");
  if (!prepared) return 0;
  auto translated = translate_cg(prepared->text, "fuzz.cg", in.stage, in.entry);
  if (!translated) {
    (void)translated.error().to_string();
    return 0;
  }
  for (const CgSemanticUse& use : translated->semantics) (void)cg_varying_location(use.mapped);
  return 0;
}
