#pragma once
// Uniform values and textures by name, for the backend tests. A missing name is an error
// that deliberately does not repeat the name, so the tests see whether the backend's
// error says which binding or sampler it was.
#include <map>
#include <string>
#include <vector>

#include "backends/Backend.h"

namespace shaderbed::test {

class MapResolver final : public UniformResolver {
 public:
  MapResolver() = default;
  explicit MapResolver(std::map<std::string, std::vector<float>> values) : values_(std::move(values)) {}
  Result<std::vector<double>> value(const UniformBlock&, const UniformMember& member) const override {
    if (auto it = values_.find(member.name); it != values_.end())
      return std::vector<double>(it->second.begin(), it->second.end());
    return fail(ErrorStage::bind, "no value bound");
  }

 private:
  std::map<std::string, std::vector<float>> values_;
};

class MapTextureResolver final : public TextureResolver {
 public:
  MapTextureResolver() = default;
  explicit MapTextureResolver(std::map<std::string, Texture> textures) : textures_(std::move(textures)) {}
  Result<const Texture*> texture(const SamplerBinding& sampler) const override {
    if (auto it = textures_.find(sampler.name); it != textures_.end()) return &it->second;
    return fail(ErrorStage::bind, "no texture bound");
  }

 private:
  std::map<std::string, Texture> textures_;
};

}  // namespace shaderbed::test
