#pragma once
// Textures for a program's samplers: each sampler (from GL introspection or the compile
// stage's reflection, binding = texture unit) is mapped to one of the job's textures and
// its SamplerSettings through the TextureResolver, checked (dimensions, cube, texel
// count, GL limits), uploaded with every mip level (GL_R32F, GL_RGBA32F, GL_RGBA8,
// GL_SRGB8_ALPHA8) and bound to its unit with the settings as texture parameters
// (filters, wrap modes, border colour, levels). The textures live for one draw.
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
  std::vector<GlTexture> textures_;   // one per distinct Texture and SamplerSettings of the job
  std::vector<GLuint> units_;
};

// Errors name the sampler; a resolver error keeps the resolver's stage and message.
// GL programs have combined samplers only (the GL-target SPIR-V of an SM4 shader has its
// Texture2D + SamplerState merged, see GlslangFrontEnd).
Result<BoundTextures> bind_textures(const GlFunctions& gl, const std::vector<SamplerBinding>& samplers,
                                    const TextureResolver* resolver);

}  // namespace shaderbed::gl
