#pragma once
// Lookup textures the harness generates on the CPU, as the book's D3DXFillTextureTX
// did: each texel holds the tabulated function at its centre, (i + 0.5) / n. The
// shaders sample them with linear filtering and clamp-to-edge (docs/models.md).
#include <map>
#include <string>
#include <vector>

#include "pipeline/Texture.h"
#include "core/Error.h"

namespace shaderbed {

using ModelParams = std::map<std::string, std::vector<double>>;

// "warn_power", "oren_nayar_angle", "ward_isotropic"; sizes and model constants come
// from the case parameters (lut_size, lut_rows, roughness, ...).
Result<Texture> generate_lut(const std::string& kind, const ModelParams& params);

// Linear filtering with clamp-to-edge, in double: what the GPU's sampler computes,
// without its rounding. Coordinates are normalised, one per dimension.
double sample_linear(const Texture& t, const double* coords);

}  // namespace shaderbed
