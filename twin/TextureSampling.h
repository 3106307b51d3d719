#pragma once
// Texture sampling on the CPU with Vulkan's rules (VK spec, "Texel Filtering"), from the
// same texel data the backends upload: what the twin's OpImageSample* and OpImageFetch
// return. Independent of harness/: the adapter copies its textures into these types.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace twin {

enum class Filter { nearest, linear };
enum class MipFilter { none, nearest, linear };
enum class Address { wrap, mirror, clamp, border };

struct SamplerState {
  Filter min_filter = Filter::linear;
  Filter mag_filter = Filter::linear;
  MipFilter mip_filter = MipFilter::none;
  Address address_u = Address::clamp, address_v = Address::clamp, address_w = Address::clamp;
  std::array<double, 4> border{0, 0, 0, 0};
  bool srgb = false;   // texels are sRGB-encoded 8-bit values: decoded to linear per texel, before filtering
};

// One texture's texels, as the device stores them.
struct TextureImage {
  uint32_t dimensions = 2;            // 1, 2 or 3
  bool cube = false;                  // six square faces (+X, -X, +Y, -Y, +Z, -Z), one after the other per level
  uint32_t width = 1, height = 1, depth = 1;   // level 0
  uint32_t channels = 4;              // 1 (R; G = B = 0, A = 1 when sampled) or 4
  bool unorm8 = false;                // texels are stored 8-bit: each float is n / 255 exactly
  // Level 0, 1, ...: channels floats per texel, x fastest, then y, then z (or face); each
  // level max(1, previous / 2) on every axis.
  std::vector<std::span<const float>> levels;
};

// Per-lane derivatives of the coordinate (d/dx and d/dy in pixels), for implicit LOD.
struct CoordinateDerivatives {
  std::array<double, 3> dx{0, 0, 0}, dy{0, 0, 0};
};

// Level of detail lambda (before clamping) from the coordinate's screen derivatives:
// log2 of the larger of the two scaled derivative lengths (VK spec's rho = max(|dx|, |dy|)
// with the coordinates scaled by the level-0 size; cube maps by their face size and the
// face's projected derivatives).
double implicit_lod(const TextureImage& image, const std::array<double, 3>& coordinate,
                    const CoordinateDerivatives& derivatives);

// Filtered RGBA at `coordinate` (normalised; a cube map's is a direction, unnormalised)
// with level of detail `lod` (implicit_lod's, or a shader's explicit Lod / Bias already
// added). Magnification when lod <= 0 uses mag_filter; otherwise min_filter, and the mip
// filter picks or blends levels clamped to those present.
std::array<double, 4> sample(const TextureImage& image, const SamplerState& sampler,
                             const std::array<double, 3>& coordinate, double lod);

// texelFetch: the texel at integer `texel` of `level`, unfiltered (sRGB decoded when
// `srgb`); out-of-range coordinates give (0, 0, 0, 0) (robust access).
std::array<double, 4> fetch(const TextureImage& image, bool srgb, const std::array<int, 3>& texel, int level);

// textureSize: the level's size (width, height, depth; a cube map's face size, depth 1).
std::array<int, 3> level_size(const TextureImage& image, int level);
int level_count(const TextureImage& image);

}  // namespace twin
