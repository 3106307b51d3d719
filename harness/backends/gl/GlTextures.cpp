#include "backends/gl/GlTextures.h"

#include <algorithm>
#include <map>
#include <string>

#include "backends/TextureShape.h"
#include "backends/gl/GlError.h"

namespace shaderbed::gl {
namespace {

std::string where(const SamplerBinding& sampler) {
  return "sampler '" + sampler.name + "' (texture unit " + std::to_string(sampler.binding) + ")";
}

GLenum texture_target(uint32_t dimensions) {
  return dimensions == 1 ? GL_TEXTURE_1D : dimensions == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D;
}

// The texture fits the sampler: same dimensionality, unused extents 1, texel count
// w*h*d, and within GL's texture size limits.
Result<void> check_texture(const GlFunctions& gl, const SamplerBinding& sampler, const Texture& t) {
  const std::string what = where(sampler) + ": texture '" + t.name + "'";
  GLint max_extent = 0;
  gl.GetIntegerv(t.dimensions == 3 ? GL_MAX_3D_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE, &max_extent);
  if (std::string problem = texture_mismatch(what, sampler, t, uint32_t(max_extent), "GL's texture"); !problem.empty())
    return std::unexpected(gl_error(problem));
  return {};
}

// R32F must be filterable for the LUT to be read as the book assumes (GL 4.5 requires
// it; GL_ARB_internalformat_query2 says whether this implementation does it fully).
Result<void> check_linear_filtering(const GlFunctions& gl, uint32_t dimensions) {
  GLint support = GL_NONE;
  gl.GetInternalformativ(texture_target(dimensions), GL_R32F, GL_FILTER, 1, &support);
  drain_gl_errors(gl);  // a query this context cannot answer leaves support at GL_NONE
  if (support == GL_FULL_SUPPORT) return {};
  return std::unexpected(gl_error("this OpenGL cannot filter " + dimensions_text(dimensions) +
                                  " GL_R32F textures linearly (GL_FILTER support " + std::to_string(support) + ")"));
}

Result<GlTexture> upload(const GlFunctions& gl, const Texture& t) {
  const GLenum target = texture_target(t.dimensions);
  GLuint name = 0;
  gl.CreateTextures(target, 1, &name);
  GlTexture texture(gl, name);
  const auto w = GLsizei(t.width), h = GLsizei(t.height), d = GLsizei(t.depth);
  // Rows of floats are 4-byte aligned and tightly packed: x fastest, then y, then z.
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl.PixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  switch (t.dimensions) {
    case 1:
      gl.TextureStorage1D(name, 1, GL_R32F, w);
      gl.TextureSubImage1D(name, 0, 0, w, GL_RED, GL_FLOAT, t.texels.data());
      break;
    case 2:
      gl.TextureStorage2D(name, 1, GL_R32F, w, h);
      gl.TextureSubImage2D(name, 0, 0, 0, w, h, GL_RED, GL_FLOAT, t.texels.data());
      break;
    default:
      gl.TextureStorage3D(name, 1, GL_R32F, w, h, d);
      gl.TextureSubImage3D(name, 0, 0, 0, 0, w, h, d, GL_RED, GL_FLOAT, t.texels.data());
      break;
  }
  // The book's LUT sampling (D3DTEXF_LINEAR, D3DTADDRESS_CLAMP, one level): bilinear or
  // trilinear within level 0, texel centres at (i + 0.5) / size.
  gl.TextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.TextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  gl.TextureParameteri(name, GL_TEXTURE_BASE_LEVEL, 0);
  gl.TextureParameteri(name, GL_TEXTURE_MAX_LEVEL, 0);
  if (auto ok = check_gl(gl, "uploading " + dimensions_text(t.dimensions) + " texture '" + t.name + "' (" + extent_text(t) + ")");
      !ok)
    return std::unexpected(ok.error());
  return texture;
}

}  // namespace

BoundTextures::~BoundTextures() {
  if (gl_ == nullptr) return;
  for (GLuint unit : units_) gl_->BindTextureUnit(unit, 0);
}

Result<BoundTextures> bind_textures(const GlFunctions& gl, const std::vector<SamplerBinding>& samplers,
                                    const TextureResolver* resolver) {
  BoundTextures bound;
  if (samplers.empty()) return bound;
  if (resolver == nullptr)
    return std::unexpected(gl_error("the program declares " + where(samplers.front()) +
                                    " but the draw has no textures (DrawJob::textures is null)"));

  // Resolve and check everything before creating any GL object.
  GLint max_units = 0;
  gl.GetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &max_units);
  std::vector<const Texture*> textures;
  std::map<uint32_t, size_t> sampler_of_unit;
  for (const SamplerBinding& sampler : samplers) {
    if (sampler.binding >= uint32_t(max_units))
      return std::unexpected(gl_error(where(sampler) + " is beyond the " + std::to_string(max_units) +
                                      " texture units GL offers"));
    auto texture = resolver->texture(sampler);
    if (!texture) {
      Error e = std::move(texture.error());
      if (e.message.find("'" + sampler.name + "'") == std::string::npos) e.message = where(sampler) + ": " + e.message;
      return std::unexpected(std::move(e).in_backend("gl"));
    }
    if (*texture == nullptr)
      return std::unexpected(gl_error(where(sampler) + ": the texture resolver returned no texture"));
    if (auto ok = check_texture(gl, sampler, **texture); !ok) return std::unexpected(ok.error());
    // Two samplers on one unit read one texture: only acceptable if it is the same one.
    auto [other, is_new] = sampler_of_unit.try_emplace(sampler.binding, textures.size());
    if (!is_new && textures[other->second] != *texture)
      return std::unexpected(gl_error(where(sampler) + " and sampler '" + samplers[other->second].name +
                                      "' share a texture unit but are bound to different textures"));
    textures.push_back(*texture);
  }
  for (const Texture* t : textures)
    if (auto ok = check_linear_filtering(gl, t->dimensions); !ok) return std::unexpected(ok.error());

  bound.gl_ = &gl;
  std::map<const Texture*, GLuint> uploaded;  // one GL texture per distinct texture of the job
  for (size_t i = 0; i < samplers.size(); ++i) {
    auto [slot, is_new] = uploaded.try_emplace(textures[i], 0);
    if (is_new) {
      auto texture = upload(gl, *textures[i]);
      if (!texture) return std::unexpected(std::move(texture.error()));
      slot->second = texture->get();
      bound.textures_.push_back(std::move(*texture));
    }
    const GLuint unit = samplers[i].binding;
    if (std::ranges::find(bound.units_, unit) != bound.units_.end()) continue;
    gl.BindTextureUnit(unit, slot->second);
    gl.BindSampler(unit, 0);  // the texture's own parameters, not a sampler object's
    bound.units_.push_back(unit);
  }
  if (auto ok = check_gl(gl, "binding lookup textures"); !ok) return std::unexpected(ok.error());
  return bound;
}

}  // namespace shaderbed::gl
