#include "backends/TextureShape.h"

#include <algorithm>

namespace shaderbed {

std::string dimensions_text(uint32_t dimensions) { return std::to_string(dimensions) + "D"; }

std::string extent_text(const Texture& t) {
  std::string text = std::to_string(t.width);
  if (t.dimensions >= 2) text += "x" + std::to_string(t.height);
  if (t.dimensions >= 3) text += "x" + std::to_string(t.depth);
  return text;
}

std::string texture_mismatch(const std::string& what, const SamplerBinding& sampler, const Texture& t,
                             uint32_t max_extent, const std::string& limit_name) {
  const std::string full = std::to_string(t.width) + "x" + std::to_string(t.height) + "x" + std::to_string(t.depth);
  if (t.dimensions < 1 || t.dimensions > 3)
    return what + " claims " + std::to_string(t.dimensions) + " dimensions; textures are 1D, 2D or 3D";
  if (t.dimensions != sampler.dimensions)
    return what + " is " + dimensions_text(t.dimensions) + " but the shader samples it as " +
           dimensions_text(sampler.dimensions);
  if (t.width == 0 || t.height == 0 || t.depth == 0) return what + " has a zero extent (" + full + ")";
  if ((t.dimensions < 2 && t.height != 1) || (t.dimensions < 3 && t.depth != 1))
    return what + " is " + dimensions_text(t.dimensions) + " but has extent " + full + " (unused extents must be 1)";
  const uint64_t texels = uint64_t(t.width) * t.height * t.depth;
  if (t.texels.size() != texels)
    return what + " (" + extent_text(t) + ") needs " + std::to_string(texels) + " texels but has " +
           std::to_string(t.texels.size());
  if (std::max({t.width, t.height, t.depth}) > max_extent)
    return what + " (" + extent_text(t) + ") exceeds " + limit_name + " " + dimensions_text(t.dimensions) +
           " limit of " + std::to_string(max_extent);
  return "";
}

}  // namespace shaderbed
