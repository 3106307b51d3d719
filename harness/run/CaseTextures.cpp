#include "run/CaseTextures.h"

namespace shaderbed {

Result<const Texture*> CaseTextures::texture(const SamplerBinding& sampler) const {
  auto it = bindings_.find(sampler.name);
  if (it == bindings_.end() || it->second.size() != 1)
    return std::unexpected(Error{.message = "sampler '" + sampler.name +
                                            "' has no binding in the case (bind it to \"lut\" under [bindings.<language>])",
                                 .file = case_path_, .stage = "bind"});
  if (it->second[0] != "lut" || lut_ == nullptr)
    return std::unexpected(Error{.message = "sampler '" + sampler.name + "' is bound to '" + it->second[0] +
                                            "', but this variant generates " + (lut_ ? "only \"lut\"" : "no lookup texture"),
                                 .file = case_path_, .stage = "bind"});
  return lut_;
}

}  // namespace shaderbed
