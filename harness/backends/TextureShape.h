#pragma once
// Whether a generated texture fits the sampler a shader declares — shared by every
// backend, which adds its own size limit and error context.
#include <cstdint>
#include <string>

#include "backends/Backend.h"

namespace shaderbed {

std::string dimensions_text(uint32_t dimensions);   // "2D"
std::string extent_text(const Texture& t);          // "256x64"

// "" when `t` fits `sampler` (same dimensionality, unused extents 1, w*h*d texels, no
// extent above max_extent); otherwise what is wrong, starting with `what`.
std::string texture_mismatch(const std::string& what, const SamplerBinding& sampler, const Texture& t,
                             uint32_t max_extent, const std::string& limit_name);

}  // namespace shaderbed
