// libFuzzer target: the case-file loader (scene/CaseFile.h) on any bytes as a case file.
// load_case reads a path, so the input is written to a scratch `cases/` folder first.
#include <cstddef>
#include <cstdint>

#include "FuzzSupport.h"
#include "scene/CaseFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  const std::string path = fuzz::write_scratch(fuzz::as_text(data, size), "cases", "fuzz.toml");
  auto loaded = load_case(path);
  if (!loaded) {
    (void)loaded.error().to_string();
    return 0;
  }
  // What the runner asks of a loaded case, beyond the fields.
  const Case& c = *loaded;
  (void)c.differential();
  for (const Language language : {Language::glsl, Language::hlsl, Language::cg})
    (void)c.textures.for_language(language);
  for (const auto& [language, table] : c.bindings)
    for (const auto& [name, binding] : table) {
      (void)binding.literal();
      (void)binding.single_name();
    }
  return 0;
}
