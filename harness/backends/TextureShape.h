#pragma once
// Whether a texture fits the sampler a shader declares — shared by every backend, which
// adds its own size limit and error context — and the sizes of its mip levels.
#include <cstdint>
#include <string>

#include "backends/Backend.h"

namespace shaderbed {

std::string dimensions_text(uint32_t dimensions);   // "2D"
std::string extent_text(const Texture& t);          // "256x64", "32x32 cube"
std::string sampler_type_text(const SamplerBinding& sampler);   // "2D", "cube"

struct LevelExtent {
  uint32_t width = 1, height = 1, depth = 1;
};
uint32_t level_count(const Texture& t);                  // 1 + mip_levels.size()
LevelExtent level_extent(const Texture& t, uint32_t level);
// Floats level `level` holds: width * height * depth * channels, times 6 for a cube.
uint64_t level_values(const Texture& t, uint32_t level);

// "" when `t` fits `sampler` (same dimensionality, cube for a cube sampler, unused extents
// 1, the texel count of every level, no extent above max_extent); otherwise what is
// wrong, starting with `what`.
std::string texture_mismatch(const std::string& what, const SamplerBinding& sampler, const Texture& t,
                             uint32_t max_extent, const std::string& limit_name);

}  // namespace shaderbed
