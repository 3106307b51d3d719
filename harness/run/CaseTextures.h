#pragma once
// Binds a shader's samplers from a case: the binding table maps a sampler's name to a
// texture the harness generated (today only the variant's LUT, called "lut").
#include "backends/Backend.h"
#include "scene/CaseFile.h"

namespace shaderbed {

class CaseTextures final : public TextureResolver {
 public:
  CaseTextures(const BindingTable& bindings, const Texture* lut, std::string case_path)
      : bindings_(bindings), lut_(lut), case_path_(std::move(case_path)) {}

  Result<const Texture*> texture(const SamplerBinding& sampler) const override;

 private:
  const BindingTable& bindings_;
  const Texture* lut_;
  std::string case_path_;
};

}  // namespace shaderbed
