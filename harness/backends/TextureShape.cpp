#include "backends/TextureShape.h"

#include <algorithm>

namespace shaderbed {

std::string dimensions_text(uint32_t dimensions) { return std::to_string(dimensions) + "D"; }

std::string extent_text(const Texture& t) {
  std::string text = std::to_string(t.width);
  if (t.dimensions >= 2) text += "x" + std::to_string(t.height);
  if (t.dimensions >= 3) text += "x" + std::to_string(t.depth);
  if (t.cube) text += " cube";
  return text;
}

std::string sampler_type_text(const SamplerBinding& sampler) {
  return sampler.cube ? "cube" : dimensions_text(sampler.dimensions);
}

uint32_t level_count(const Texture& t) { return 1 + uint32_t(t.mip_levels.size()); }

LevelExtent level_extent(const Texture& t, uint32_t level) {
  const auto half = [&](uint32_t n) { return std::max(1u, n >> level); };
  return {half(t.width), t.dimensions >= 2 ? half(t.height) : 1, t.dimensions >= 3 ? half(t.depth) : 1};
}

uint64_t level_values(const Texture& t, uint32_t level) {
  const LevelExtent e = level_extent(t, level);
  return uint64_t(e.width) * e.height * e.depth * channels(t.format) * (t.cube ? 6 : 1);
}

std::string texture_mismatch(const std::string& what, const SamplerBinding& sampler, const Texture& t,
                             uint32_t max_extent, const std::string& limit_name) {
  const std::string full = std::to_string(t.width) + "x" + std::to_string(t.height) + "x" + std::to_string(t.depth);
  if (t.dimensions < 1 || t.dimensions > 3)
    return what + " claims " + std::to_string(t.dimensions) + " dimensions; textures are 1D, 2D or 3D";
  if (t.cube != sampler.cube || t.dimensions != sampler.dimensions)
    return what + " is " + (t.cube ? std::string("a cube map") : dimensions_text(t.dimensions)) +
           " but the shader samples it as " + (sampler.cube ? std::string("a cube map") : sampler_type_text(sampler));
  if (t.width == 0 || t.height == 0 || t.depth == 0) return what + " has a zero extent (" + full + ")";
  if ((t.dimensions < 2 && t.height != 1) || (t.dimensions < 3 && t.depth != 1))
    return what + " is " + dimensions_text(t.dimensions) + " but has extent " + full + " (unused extents must be 1)";
  if (t.cube && t.width != t.height) return what + " is a cube map with non-square faces (" + extent_text(t) + ")";
  for (uint32_t level = 0; level < level_count(t); ++level) {
    const std::vector<float>& values = level == 0 ? t.texels : t.mip_levels[level - 1];
    if (values.size() != level_values(t, level))
      return what + " (" + extent_text(t) + ", " + to_string(t.format) + ") needs " +
             std::to_string(level_values(t, level)) + (channels(t.format) == 1 ? " texels" : " values") +
             (level == 0 ? std::string() : " at mip level " + std::to_string(level)) + " but has " +
             std::to_string(values.size());
  }
  uint32_t max_levels = 1;
  for (uint32_t n = std::max({t.width, t.height, t.depth}); n > 1; n >>= 1) ++max_levels;
  if (level_count(t) > max_levels)
    return what + " has " + std::to_string(level_count(t)) + " mip levels; " + extent_text(t) + " has at most " +
           std::to_string(max_levels);
  if (std::max({t.width, t.height, t.depth}) > max_extent)
    return what + " (" + extent_text(t) + ") exceeds " + limit_name + " " + dimensions_text(t.dimensions) +
           " limit of " + std::to_string(max_extent);
  return "";
}

}  // namespace shaderbed
