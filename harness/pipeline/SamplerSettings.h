#pragma once
// How a texture is sampled: what a DX9 effect's sampler_state block or a case's
// [textures] entry says, and what both backends honour (VkSamplerCreateInfo, GL sampler
// parameters). The defaults are the generated LUTs': linear, no mipmaps, clamp to edge.
#include <array>
#include <optional>
#include <string>

namespace shaderbed {

enum class TextureFilter { nearest, linear };
enum class MipFilter { none, nearest, linear };
enum class AddressMode { wrap, mirror, clamp, border };

struct SamplerSettings {
  TextureFilter min_filter = TextureFilter::linear;
  TextureFilter mag_filter = TextureFilter::linear;
  MipFilter mip_filter = MipFilter::none;
  AddressMode address_u = AddressMode::clamp;
  AddressMode address_v = AddressMode::clamp;
  AddressMode address_w = AddressMode::clamp;
  float border_color[4] = {0, 0, 0, 0};
  bool srgb = false;   // texels are sRGB-encoded: decoded to linear when sampled
  bool operator==(const SamplerSettings&) const = default;
};

// Part of a SamplerSettings, as one source states it (a case entry states only what it
// names); unset fields keep what the source below said. Order, lowest first: the
// defaults, an effect's sampler_state, the case's entry for the sampler state, the
// case's entry for the texture.
struct SamplerSettingsPatch {
  std::optional<TextureFilter> min_filter, mag_filter;
  std::optional<MipFilter> mip_filter;
  std::optional<AddressMode> address_u, address_v, address_w;
  std::optional<std::array<float, 4>> border_color;
  std::optional<bool> srgb;
  bool operator==(const SamplerSettingsPatch&) const = default;

  SamplerSettings applied_to(SamplerSettings s) const {
    if (min_filter) s.min_filter = *min_filter;
    if (mag_filter) s.mag_filter = *mag_filter;
    if (mip_filter) s.mip_filter = *mip_filter;
    if (address_u) s.address_u = *address_u;
    if (address_v) s.address_v = *address_v;
    if (address_w) s.address_w = *address_w;
    if (border_color)
      for (int i = 0; i < 4; ++i) s.border_color[i] = (*border_color)[size_t(i)];
    if (srgb) s.srgb = *srgb;
    return s;
  }
};

inline const char* to_string(TextureFilter f) { return f == TextureFilter::nearest ? "nearest" : "linear"; }
inline const char* to_string(MipFilter f) {
  return f == MipFilter::none ? "none" : f == MipFilter::nearest ? "nearest" : "linear";
}
inline const char* to_string(AddressMode a) {
  switch (a) {
    case AddressMode::wrap: return "wrap";
    case AddressMode::mirror: return "mirror";
    case AddressMode::clamp: return "clamp";
    case AddressMode::border: return "border";
  }
  return "?";
}

}  // namespace shaderbed
