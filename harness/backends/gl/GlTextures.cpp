#include "backends/gl/GlTextures.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "backends/TextureShape.h"
#include "backends/gl/GlError.h"

namespace shaderbed::gl {
namespace {

std::string where(const SamplerBinding& sampler) {
  return "sampler '" + sampler.name + "' (texture unit " + std::to_string(sampler.binding) + ")";
}

GLenum texture_target(const Texture& t) {
  if (t.cube) return GL_TEXTURE_CUBE_MAP;
  return t.dimensions == 1 ? GL_TEXTURE_1D : t.dimensions == 2 ? GL_TEXTURE_2D : GL_TEXTURE_3D;
}

struct GlFormat {
  GLenum internal, format, type;
};

GlFormat gl_format(TexelFormat f) {
  switch (f) {
    case TexelFormat::r32_float: return {GL_R32F, GL_RED, GL_FLOAT};
    case TexelFormat::rgba32_float: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case TexelFormat::rgba8_unorm: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case TexelFormat::rgba8_srgb: return {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE};
  }
  return {GL_R32F, GL_RED, GL_FLOAT};
}

// The texture fits the sampler: same dimensionality, unused extents 1, texel count of
// every level, and within GL's texture size limits.
Result<void> check_texture(const GlFunctions& gl, const SamplerBinding& sampler, const Texture& t) {
  const std::string what = where(sampler) + ": texture '" + t.name + "'";
  GLint max_extent = 0;
  gl.GetIntegerv(t.cube ? GL_MAX_CUBE_MAP_TEXTURE_SIZE : t.dimensions == 3 ? GL_MAX_3D_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE,
                 &max_extent);
  if (std::string problem = texture_mismatch(what, sampler, t, uint32_t(max_extent), "GL's texture"); !problem.empty())
    return std::unexpected(gl_error(problem));
  return {};
}

bool uses_linear(const SamplerSettings& s) {
  return s.min_filter == TextureFilter::linear || s.mag_filter == TextureFilter::linear ||
         s.mip_filter == MipFilter::linear;
}

// The format must be filterable when the settings filter linearly (GL 4.5 requires it for
// these formats; GL_ARB_internalformat_query2 says whether this implementation does it).
Result<void> check_linear_filtering(const GlFunctions& gl, const Texture& t) {
  GLint support = GL_NONE;
  gl.GetInternalformativ(texture_target(t), gl_format(t.format).internal, GL_FILTER, 1, &support);
  drain_gl_errors(gl);  // a query this context cannot answer leaves support at GL_NONE
  if (support == GL_FULL_SUPPORT) return {};
  return std::unexpected(gl_error("this OpenGL cannot filter " + extent_text(t) + " " + to_string(t.format) +
                                  " textures linearly (GL_FILTER support " + std::to_string(support) + ")"));
}

GLint wrap_mode(AddressMode a) {
  switch (a) {
    case AddressMode::wrap: return GL_REPEAT;
    case AddressMode::mirror: return GL_MIRRORED_REPEAT;
    case AddressMode::clamp: return GL_CLAMP_TO_EDGE;
    case AddressMode::border: return GL_CLAMP_TO_BORDER;
  }
  return GL_CLAMP_TO_EDGE;
}

GLint min_filter(const SamplerSettings& s) {
  const bool linear = s.min_filter == TextureFilter::linear;
  switch (s.mip_filter) {
    case MipFilter::none: return linear ? GL_LINEAR : GL_NEAREST;
    case MipFilter::nearest: return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    case MipFilter::linear: return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

// 8-bit formats as round(v * 255): the loader stored the file's bytes / 255, so exact.
std::vector<uint8_t> unorm8(const std::vector<float>& values) {
  std::vector<uint8_t> bytes(values.size());
  for (size_t i = 0; i < values.size(); ++i) bytes[i] = uint8_t(std::lround(std::clamp(values[i], 0.0f, 1.0f) * 255.0f));
  return bytes;
}

Result<GlTexture> upload(const GlFunctions& gl, const Texture& t, const SamplerSettings& s) {
  const GLenum target = texture_target(t);
  GLuint name = 0;
  gl.CreateTextures(target, 1, &name);
  GlTexture texture(gl, name);
  const GlFormat f = gl_format(t.format);
  const auto levels = GLsizei(level_count(t));
  // Rows are tightly packed: x fastest, then y, then z (or cube face).
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  gl.PixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  switch (t.cube ? 2 : t.dimensions) {
    case 1: gl.TextureStorage1D(name, levels, f.internal, GLsizei(t.width)); break;
    case 2: gl.TextureStorage2D(name, levels, f.internal, GLsizei(t.width), GLsizei(t.height)); break;
    default: gl.TextureStorage3D(name, levels, f.internal, GLsizei(t.width), GLsizei(t.height), GLsizei(t.depth)); break;
  }
  for (uint32_t level = 0; level < level_count(t); ++level) {
    const std::vector<float>& values = level == 0 ? t.texels : t.mip_levels[level - 1];
    std::vector<uint8_t> bytes;
    const void* data = values.data();
    if (f.type == GL_UNSIGNED_BYTE) {
      bytes = unorm8(values);
      data = bytes.data();
    }
    const LevelExtent e = level_extent(t, level);
    const auto w = GLsizei(e.width), h = GLsizei(e.height), d = GLsizei(e.depth);
    const auto l = GLint(level);
    if (t.cube)  // DSA addresses a cube map's faces as layers 0..5
      gl.TextureSubImage3D(name, l, 0, 0, 0, w, h, 6, f.format, f.type, data);
    else if (t.dimensions == 1)
      gl.TextureSubImage1D(name, l, 0, w, f.format, f.type, data);
    else if (t.dimensions == 2)
      gl.TextureSubImage2D(name, l, 0, 0, w, h, f.format, f.type, data);
    else
      gl.TextureSubImage3D(name, l, 0, 0, 0, w, h, d, f.format, f.type, data);
  }
  // The defaults are the book's LUT sampling (D3DTEXF_LINEAR, D3DTADDRESS_CLAMP, one
  // level): bilinear or trilinear within level 0, texel centres at (i + 0.5) / size.
  gl.TextureParameteri(name, GL_TEXTURE_MIN_FILTER, min_filter(s));
  gl.TextureParameteri(name, GL_TEXTURE_MAG_FILTER, s.mag_filter == TextureFilter::linear ? GL_LINEAR : GL_NEAREST);
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_S, wrap_mode(s.address_u));
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_T, wrap_mode(s.address_v));
  gl.TextureParameteri(name, GL_TEXTURE_WRAP_R, wrap_mode(s.address_w));
  gl.TextureParameterfv(name, GL_TEXTURE_BORDER_COLOR, s.border_color);
  gl.TextureParameteri(name, GL_TEXTURE_BASE_LEVEL, 0);
  gl.TextureParameteri(name, GL_TEXTURE_MAX_LEVEL, s.mip_filter == MipFilter::none ? 0 : levels - 1);
  // Cube faces are filtered as one surface, as in D3D10+ and Vulkan.
  if (t.cube) gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  if (auto ok = check_gl(gl, "uploading texture '" + t.name + "' (" + extent_text(t) + ", " + to_string(t.format) +
                                 ", " + std::to_string(levels) + " levels)");
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
  struct Use {
    const Texture* texture;
    SamplerSettings settings;
    bool operator==(const Use&) const = default;
  };
  std::vector<Use> uses;
  std::map<uint32_t, size_t> sampler_of_unit;
  const auto with_context = [&](const SamplerBinding& sampler, Error e) {
    if (e.message.find("'" + sampler.name + "'") == std::string::npos) e.message = where(sampler) + ": " + e.message;
    return std::unexpected(std::move(e).in_backend("gl"));
  };
  for (const SamplerBinding& sampler : samplers) {
    if (sampler.kind != SamplerKind::combined)
      return std::unexpected(gl_error(where(sampler) + " is a separate " +
                                      (sampler.kind == SamplerKind::image ? "texture" : "sampler state") +
                                      "; GL programs sample combined samplers only"));
    if (sampler.binding >= uint32_t(max_units))
      return std::unexpected(gl_error(where(sampler) + " is beyond the " + std::to_string(max_units) +
                                      " texture units GL offers"));
    auto texture = resolver->texture(sampler);
    if (!texture) return with_context(sampler, std::move(texture.error()));
    if (*texture == nullptr)
      return std::unexpected(gl_error(where(sampler) + ": the texture resolver returned no texture"));
    if (auto ok = check_texture(gl, sampler, **texture); !ok) return std::unexpected(ok.error());
    auto settings = resolver->settings(sampler);
    if (!settings) return with_context(sampler, std::move(settings.error()));
    const Use use{*texture, *settings};
    // Two samplers on one unit read one texture: only acceptable if it is the same one.
    auto [other, is_new] = sampler_of_unit.try_emplace(sampler.binding, uses.size());
    if (!is_new && uses[other->second] != use)
      return std::unexpected(gl_error(where(sampler) + " and sampler '" + samplers[other->second].name +
                                      "' share a texture unit but are bound to different textures or settings"));
    uses.push_back(use);
  }
  for (const Use& use : uses)
    if (uses_linear(use.settings))
      if (auto ok = check_linear_filtering(gl, *use.texture); !ok) return std::unexpected(ok.error());

  bound.gl_ = &gl;
  // One GL texture per distinct texture and settings of the job: the settings are the
  // texture's own parameters.
  std::vector<std::pair<Use, GLuint>> uploaded;
  for (size_t i = 0; i < samplers.size(); ++i) {
    auto slot = std::ranges::find(uploaded, uses[i], &std::pair<Use, GLuint>::first);
    if (slot == uploaded.end()) {
      auto texture = upload(gl, *uses[i].texture, uses[i].settings);
      if (!texture) return std::unexpected(std::move(texture.error()));
      uploaded.emplace_back(uses[i], texture->get());
      slot = uploaded.end() - 1;
      bound.textures_.push_back(std::move(*texture));
    }
    const GLuint unit = samplers[i].binding;
    if (std::ranges::find(bound.units_, unit) != bound.units_.end()) continue;
    gl.BindTextureUnit(unit, slot->second);
    gl.BindSampler(unit, 0);  // the texture's own parameters, not a sampler object's
    bound.units_.push_back(unit);
  }
  if (auto ok = check_gl(gl, "binding textures"); !ok) return std::unexpected(ok.error());
  return bound;
}

}  // namespace shaderbed::gl
