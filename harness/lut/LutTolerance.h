#pragma once
// How far a LUT variant can legitimately differ from the analytic model: the largest
// difference between the filtered LUT and the exact tabulated function, weighted by
// the factors the shader multiplies it with, over the function's domain. Derived from
// the LUT's size (and the model's parameters), not tuned.
#include <string>
#include <vector>

#include "core/Error.h"
#include "lut/LookupTexture.h"

namespace shaderbed {

struct LutErrorBound {
  double max_abs = 0;          // bound on |LUT shading - analytic shading| per channel, interior
  double band_max_abs = 0;     // the same for the silhouette band, where N.V reaches 0
  std::string derivation;      // one line: what was maximised over which domain
};

// One drawn pixel's shading configuration as a LUT variant's shader sees it: what it
// looks the term up by, and the factors outside the LUT it multiplies the term with.
struct LutSample {
  double n_dot_l = 0, n_dot_v = 0, n_dot_h = 0;   // unit N, L, V, H (L = Lp for point lights)
  double cos_azimuth = 1;    // Oren-Nayar's cosC: the B term's factor besides the LUT
  double spot_cos = 0;       // Warn: Lp . L, the power LUT's base
  double light_scale = 1;    // Warn: max(diffuse) * max(light_color) / d^2 at the point
};

// The configurations one shape shows in the drawn image: its interior pixels exactly, and
// for the silhouette band the covered pixels around each band pixel with their attributes
// extrapolated one pixel further (edge pixels shade attributes past the triangle).
struct LutDomain {
  std::string shape;
  std::vector<LutSample> interior;
  std::vector<LutSample> band;
};

// The bound over the whole function domain (every configuration the LUT can be asked
// for). `light_scale` bounds the factors outside the LUT that the model does not know by
// itself (Warn: the largest diffuse * light_color / d^2 over the shape).
Result<LutErrorBound> lut_error_bound(const std::string& kind, const ModelParams& params, const Texture& lut,
                                      double light_scale);

// The bound over what one shape shows: the largest weighted |filtered LUT - exact term|
// at the domain's configurations. Much tighter than the whole-domain bound, so a lookup
// that is off by a texel on this shape exceeds it (the table's worst corner, e.g. N.L -> 0
// on the terminator, is not on every shape).
Result<LutErrorBound> lut_error_bound(const std::string& kind, const ModelParams& params, const Texture& lut,
                                      const LutDomain& domain);

}  // namespace shaderbed
