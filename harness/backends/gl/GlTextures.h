#pragma once
// Lookup textures for a program's samplers: each sampler (from GL introspection or the
// compile stage's reflection, binding = texture unit) is mapped to one of the job's
// textures through the TextureResolver, checked (dimensions, texel count, GL limits),
// uploaded as GL_R32F and bound to its unit with linear filtering, no mipmaps and
// clamp-to-edge on every axis. The textures live for one draw.
#include <vector>

#include "backends/Backend.h"
#include "backends/gl/GlObject.h"
#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed::gl {

class BoundTextures {
 public:
  BoundTextures() = default;
  BoundTextures(BoundTextures&&) noexcept = default;
  BoundTextures& operator=(BoundTextures&&) noexcept = default;
  // Unbinds the units (the textures are deleted with the object); the context must be current.
  ~BoundTextures();

 private:
  friend Result<BoundTextures> bind_textures(const GlFunctions&, const std::vector<SamplerBinding>&,
                                             const TextureResolver*);
  const GlFunctions* gl_ = nullptr;
  std::vector<GlTexture> textures_;   // one per distinct Texture of the job
  std::vector<GLuint> units_;
};

// Errors name the sampler; a resolver error keeps the resolver's stage and message.
Result<BoundTextures> bind_textures(const GlFunctions& gl, const std::vector<SamplerBinding>& samplers,
                                    const TextureResolver* resolver);

}  // namespace shaderbed::gl
