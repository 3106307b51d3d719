#pragma once
// How far a LUT variant can legitimately differ from the analytic model: the largest
// difference between the filtered LUT and the exact tabulated function, weighted by
// the factors the shader multiplies it with, over the function's domain. Derived from
// the LUT's size (and the model's parameters), not tuned.
#include <string>

#include "core/Error.h"
#include "lut/LookupTexture.h"

namespace shaderbed {

struct LutErrorBound {
  double max_abs = 0;          // bound on |LUT shading - analytic shading| per channel, interior
  double band_max_abs = 0;     // the same for the silhouette band, where N.V reaches 0
  std::string derivation;      // one line: what was maximised over which domain
};

// `light_scale` bounds the factors outside the LUT that the model does not know by
// itself (Warn: the largest diffuse * light_color / d^2 over the shape).
Result<LutErrorBound> lut_error_bound(const std::string& kind, const ModelParams& params, const Texture& lut,
                                      double light_scale);

}  // namespace shaderbed
