#pragma once
// Why a failing render differs from its reference: the render is fitted against the
// reference through a small, named set of conventions a shader port typically gets
// wrong (a 1/π, an extra N·L, gamma, clamping, a half-pixel offset, a negated vector,
// ...), and each explanation reports how well it fits. Pure functions: no I/O, no driver.
// This only explains: it never turns a fail into a pass.
//
// Each explanation is a transform T of the reference (or, for "the render does not
// clamp", of the render), and is fitted on the reference's interior pixels the render
// drew with finite RGB on both sides. Its residual is the largest |render − T(reference)|
// over those pixels and channels; it fits when every fitted channel is within the
// interior tolerance (|a − b| <= interior_max_abs + interior_max_rel·|b|, b the explained
// reference) AND every pixel that failed the plain comparison is among the fitted ones:
// an explanation may not skip the pixels it is meant to explain. (One deliberate
// exception, which checks what it claims instead: "not gated by N·L", fitted where
// N·L > 0, requires every failing pixel to lie where N·L <= 0 with a black reference.)
//
// The explanations, by stable name (a family of variants reports only its best one):
//  - constant_factor: render ≈ k·reference, k by least squares over all fitted channels,
//    named when within 1e-3 (relative) of π, 1/π, 2π, 1/2π, 4π, 1/4π, 2, 1/2, or for a
//    scalar parameter n of (n+2)/2π, (n+8)/8π, (n+1)/2π or an inverse. A model with an
//    ambient term scaled along with the rest does not fit a plain factor (the ambient
//    part is not scaled), so it shows as an incomplete fit.
//  - extra_n_dot_l, missing_n_dot_l: render ≈ reference·max(N·L, 0), ≈ reference / N·L
//    (pixels with N·L <= 1e-6 cannot be divided: a failing one there means no fit).
//  - gated_by_n_dot_l: render ≈ reference·[N·L > 0] (the render gates, the reference not);
//    not_gated_by_n_dot_l: the other way round, checked as described above.
//  - unnormalised_normal: render ≈ reference·|n|^e, e by least squares on log ratios
//    (≈ 1 for a diffuse term, ≈ the exponent for a specular lobe).
//  - gamma (best of gamma_encoded_render, gamma_decoded_render, srgb_encoded_render,
//    srgb_decoded_render): render ≈ f(max(reference, 0)), f = x^(1/2.2), x^2.2, the sRGB
//    encoding or decoding: the render applies f where the reference does not.
//  - render_clamps: render ≈ clamp(reference, 0, 1); render_does_not_clamp:
//    clamp(render, 0, 1) ≈ reference.
//  - half_pixel_offset: render ≈ the reference resampled bilinearly at (x ± 0.5, y ± 0.5)
//    (D3D9 pixel centres), best of the four signs. The resampling reads the reference at
//    covered neighbours; every interior pixel has all eight, so no pixel is skipped.
//  - each counterfactual: render ≈ that image (the reference re-rendered under a
//    convention: light or eye negated, normal not renormalised, L and V from the vertex
//    stage, the faceted normal, matrices transposed,
//    texture v flipped), fitted on pixels it covers, under the caller's name.
// The N·L and |n| explanations need surface samples and each counterfactual its image:
// without them (or with a size that does not match) they are absent from the list.
#include <map>
#include <span>
#include <string>
#include <vector>

#include "compare/ImageComparison.h"
#include "compare/SurfaceSamples.h"
#include "core/Image.h"

namespace shaderbed {

// The reference re-rendered under a convention (reference::Perturbation and the like).
struct Counterfactual {
  std::string name;    // stable id, e.g. "negated_light"
  std::string detail;  // reads after "re-rendered with": "the light vector negated (L → −L)"
  const ReferenceImage* image = nullptr;
};

// What the fit may use besides the two images; every part is optional.
struct ConventionEvidence {
  const SurfaceSamples* surface = nullptr;           // same size as the reference
  std::span<const Counterfactual> counterfactuals;
  std::map<std::string, double> parameters;          // the case's scalar parameters, to name constants
};

struct ConventionFit {
  std::string name;         // stable id ("constant_factor", "extra_n_dot_l", a counterfactual's name, ...)
  std::string description;  // reads after "matches the reference": "× π (1/π normalisation in the reference only)"
  double residual = 0;      // max |render − explained reference| over the fitted channels
  double rmse = 0;          // over the same channels
  size_t pixels = 0;        // pixels fitted
  bool fits = false;        // within the interior tolerance on every fitted channel, failing pixels included
};

// Every explanation the evidence allows, fitting ones first, each group by residual.
// Empty when there is nothing to explain: no interior pixel the render drew with finite
// colour fails the plain comparison (the render passes, or fails only on coverage or
// non-finite values, which no colour convention explains). When the render drew NaN/Inf
// on interior pixels where the reference is finite (or the reverse), only counterfactuals
// that are non-finite at exactly those pixels remain: no fit of the finite rest is offered
// beside pixels it does not explain.
// `classes`: classify_pixels(reference).
std::vector<ConventionFit> explain_difference(const Image& render, const ReferenceImage& reference,
                                              const std::vector<PixelClass>& classes,
                                              const ComparisonThresholds& thresholds,
                                              const ConventionEvidence& evidence = {});

// One line: "matches the reference × π (1/π normalisation in the reference only) to 2e-6",
// or for a fit that does not hold "× 1.73 fits only to 0.04 (incomplete)".
std::string describe(const ConventionFit& fit);

}  // namespace shaderbed
