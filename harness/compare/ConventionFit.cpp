#include "compare/ConventionFit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

namespace shaderbed {
namespace {

constexpr double kPi = std::numbers::pi;
using Rgb = std::array<double, 3>;

// Surface samples with N·L at or below this are not divided by (missing_n_dot_l).
constexpr double kSmallestDivisor = 1e-6;

// A family's variants (gamma curves, half-pixel signs) are told apart on every 8th fitted
// pixel; only the one reported is fitted on all. They differ far more than that hides.
constexpr size_t kSelectionStride = 8;

// The interior tolerance, per channel, as compare_images() applies it.
struct Tolerance {
  double max_abs = 0;
  double max_rel = 0;
  bool within(double render, double reference) const {
    return std::abs(render - reference) <= max_abs + max_rel * std::abs(reference);
  }
};

// Everything one explanation is fitted on: the images, and the pixels every explanation
// must account for (interior, drawn, finite RGB on both sides), with which of them fail
// the plain comparison.
struct FitInputs {
  const ReferenceImage& reference;
  Tolerance tolerance;
  // Parallel, one entry per fitted pixel (gathered once: every explanation walks them).
  std::vector<size_t> pixels;
  std::vector<Rgb> render_values;
  std::vector<Rgb> reference_values;
  std::vector<uint8_t> failed;
  size_t failed_count = 0;
};

bool finite(const Rgb& rgb) { return std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]); }

FitInputs fit_inputs(const Image& render, const ReferenceImage& reference, const std::vector<PixelClass>& classes,
                     const ComparisonThresholds& thresholds) {
  FitInputs in{reference, {thresholds.interior_max_abs, thresholds.interior_max_rel}, {}, {}, {}, {}, 0};
  const size_t interior = size_t(std::count(classes.begin(), classes.end(), PixelClass::interior));
  in.pixels.reserve(interior);
  in.render_values.reserve(interior);
  in.reference_values.reserve(interior);
  in.failed.reserve(interior);
  for (size_t pixel = 0; pixel < classes.size(); ++pixel) {
    if (classes[pixel] != PixelClass::interior || !render.coverage[pixel]) continue;
    const float* p = &render.rgba[pixel * 4];
    const Rgb q{p[0], p[1], p[2]};
    const Rgb r{reference.rgba[pixel * 4], reference.rgba[pixel * 4 + 1], reference.rgba[pixel * 4 + 2]};
    if (!finite(q) || !finite(r)) continue;
    bool failed = false;
    for (int c = 0; c < 3; ++c) failed = failed || !in.tolerance.within(q[c], r[c]);
    in.pixels.push_back(pixel);
    in.render_values.push_back(q);
    in.reference_values.push_back(r);
    in.failed.push_back(failed ? 1 : 0);
    in.failed_count += failed ? 1 : 0;
  }
  return in;
}

// One explanation evaluated over the fit pixels.
struct Tally {
  double residual = 0;
  double sum_squares = 0;
  size_t channels = 0;
  size_t pixels = 0;
  bool within = true;            // every evaluated channel within tolerance
  size_t failed_not_evaluated = 0;
};

// explain(pixel, render, reference) turns the pixel's RGB (given as they are) into what
// the explanation compares, in place, or returns false where it cannot be evaluated.
// `stride` > 1 evaluates every stride-th pixel only (to choose among variants).
template <class Explain>
Tally evaluate(const FitInputs& in, Explain&& explain, size_t stride = 1) {
  Tally tally;
  for (size_t k = 0; k < in.pixels.size(); k += stride) {
    const size_t pixel = in.pixels[k];
    Rgb q = in.render_values[k], r = in.reference_values[k];
    if (!explain(pixel, q, r)) {
      tally.failed_not_evaluated += in.failed[k];
      continue;
    }
    ++tally.pixels;
    for (int c = 0; c < 3; ++c) {
      const double difference = std::abs(q[c] - r[c]);
      tally.residual = std::max(tally.residual, std::isnan(difference) ? INFINITY : difference);
      tally.sum_squares += difference * difference;
      ++tally.channels;
      tally.within = tally.within && in.tolerance.within(q[c], r[c]);
    }
  }
  return tally;
}

// `failures_accounted`: every plainly failing pixel is explained (normally: evaluated).
ConventionFit fit_of(std::string name, std::string description, const Tally& tally, bool failures_accounted) {
  ConventionFit fit{std::move(name), std::move(description), tally.residual,
                    tally.channels ? std::sqrt(tally.sum_squares / double(tally.channels)) : 0.0, tally.pixels,
                    false};
  fit.fits = tally.within && tally.pixels > 0 && failures_accounted && std::isfinite(tally.residual);
  return fit;
}

ConventionFit fit_of(std::string name, std::string description, const Tally& tally) {
  return fit_of(std::move(name), std::move(description), tally, tally.failed_not_evaluated == 0);
}

// The order of the list: fitting ones first, then the smaller residual.
bool better(const ConventionFit& a, const ConventionFit& b) {
  if (a.fits != b.fits) return a.fits;
  return a.residual < b.residual;
}

// The same order on (sampled) tallies, to choose a family's variant.
bool better_sample(const Tally& a, const Tally& b) {
  const bool a_fits = a.within && a.failed_not_evaluated == 0, b_fits = b.within && b.failed_not_evaluated == 0;
  if (a_fits != b_fits) return a_fits;
  return a.residual < b.residual;
}

// The index of the family's best variant, explain_variant(i) giving variant i's explain.
template <class ExplainVariant>
size_t best_variant(const FitInputs& in, size_t variants, ExplainVariant&& explain_variant) {
  size_t best = 0;
  Tally best_tally;
  for (size_t i = 0; i < variants; ++i) {
    const Tally tally = evaluate(in, explain_variant(i), kSelectionStride);
    if (i == 0 || better_sample(tally, best_tally)) {
      best = i;
      best_tally = tally;
    }
  }
  return best;
}

// 2e-6, 3.5e-7, 0.04, 1.7: two significant digits, no exponent padding.
std::string short_number(double value) {
  if (!std::isfinite(value)) return "inf";
  if (value == 0) return "0";
  if (std::abs(value) >= 1e-3 && std::abs(value) < 100) return fmt::format("{:.2g}", value);
  const std::string text = fmt::format("{:.1e}", value);  // "2.0e-06"
  const size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.ends_with(".0")) mantissa.resize(mantissa.size() - 2);
  return fmt::format("{}e{}", mantissa, std::stoi(text.substr(e + 1)));
}

// ---- 1. constant factor ------------------------------------------------------------------

struct NamedConstant {
  double value;
  std::string label;  // "π", "(power+2)/2π with power = 7"
  std::string note;   // "1/π normalisation in the reference only"
};

std::vector<NamedConstant> named_constants(const std::map<std::string, double>& parameters) {
  std::vector<NamedConstant> constants{
      {kPi, "π", "1/π normalisation in the reference only"},
      {1 / kPi, "1/π", "1/π normalisation in the render only"},
      {2 * kPi, "2π", "1/2π normalisation in the reference only"},
      {1 / (2 * kPi), "1/2π", "1/2π normalisation in the render only"},
      {4 * kPi, "4π", "1/4π normalisation in the reference only"},
      {1 / (4 * kPi), "1/4π", "1/4π normalisation in the render only"},
      {2, "2", "a factor of 2 in the render only"},
      {0.5, "1/2", "a factor of 1/2 in the render only"},
  };
  struct Normalisation {
    double offset, divisor;  // (n + offset) / (divisor·π)
    const char* what;
  };
  for (const auto& [name, n] : parameters) {
    if (!std::isfinite(n)) continue;
    for (const Normalisation& form : {Normalisation{2, 2, "energy-normalised Phong lobe"},
                                      Normalisation{8, 8, "energy-normalised Blinn-Phong lobe"},
                                      Normalisation{1, 2, "Phong lobe normalised to unit integral"}}) {
      const double value = (n + form.offset) / (form.divisor * kPi);
      if (!(value > 0)) continue;
      const std::string with = fmt::format(" with {} = {:g}", name, n);
      const std::string pi = form.divisor == 1 ? "π" : fmt::format("{:g}π", form.divisor);
      constants.push_back({value, fmt::format("({}+{:g})/{}{}", name, form.offset, pi, with),
                           fmt::format("{} in the render only", form.what)});
      constants.push_back({1 / value, fmt::format("{}/({}+{:g}){}", pi, name, form.offset, with),
                           fmt::format("{} in the reference only", form.what)});
    }
  }
  return constants;
}

std::string factor_description(double k, const std::map<std::string, double>& parameters) {
  const NamedConstant* nearest = nullptr;
  double nearest_distance = 1e-3;  // relative
  const std::vector<NamedConstant> constants = named_constants(parameters);
  for (const NamedConstant& constant : constants) {
    const double distance = std::abs(k / constant.value - 1);
    if (distance <= nearest_distance) {
      nearest = &constant;
      nearest_distance = distance;
    }
  }
  if (!nearest) return fmt::format("× {:.3g}", k);
  return fmt::format("× {} ({})", nearest->label, nearest->note);
}

void constant_factor(const FitInputs& in, const std::map<std::string, double>& parameters,
                     std::vector<ConventionFit>& out) {
  double render_dot_reference = 0, reference_squared = 0;
  for (size_t k = 0; k < in.pixels.size(); ++k) {
    const Rgb &q = in.render_values[k], &r = in.reference_values[k];
    for (int c = 0; c < 3; ++c) {
      render_dot_reference += q[c] * r[c];
      reference_squared += r[c] * r[c];
    }
  }
  if (!(reference_squared > 0)) return;  // a black reference: no factor to fit
  const double k = render_dot_reference / reference_squared;
  const Tally tally = evaluate(in, [k](size_t, Rgb&, Rgb& r) {
    for (double& channel : r) channel *= k;
    return true;
  });
  out.push_back(fit_of("constant_factor", factor_description(k, parameters), tally));
}

// ---- 2-4. explanations on the surface samples ---------------------------------------------

void surface_explanations(const FitInputs& in, const SurfaceSamples& surface, std::vector<ConventionFit>& out) {
  const auto& n_dot_l = surface.n_dot_l;
  const auto& length = surface.normal_length;

  out.push_back(fit_of("extra_n_dot_l", "× N·L (an extra N·L factor in the render)",
                       evaluate(in, [&](size_t pixel, Rgb&, Rgb& r) {
                         const double factor = std::max(0.0, n_dot_l[pixel]);
                         for (double& channel : r) channel *= factor;
                         return true;
                       })));
  out.push_back(fit_of("missing_n_dot_l", "÷ N·L (the render lacks the reference's N·L factor)",
                       evaluate(in, [&](size_t pixel, Rgb&, Rgb& r) {
                         if (!(n_dot_l[pixel] > kSmallestDivisor)) return false;
                         for (double& channel : r) channel /= n_dot_l[pixel];
                         return true;
                       })));
  out.push_back(fit_of("gated_by_n_dot_l", "× [N·L > 0] (the render gates by N·L > 0, the reference does not)",
                       evaluate(in, [&](size_t pixel, Rgb&, Rgb& r) {
                         if (!(n_dot_l[pixel] > 0)) r = {0, 0, 0};
                         return true;
                       })));

  // Not gated: equal where N·L > 0, and every failing pixel where N·L <= 0 on a reference
  // black there (the reference's gate shut, the render's light through).
  const Tally lit = evaluate(in, [&](size_t pixel, Rgb&, Rgb&) { return n_dot_l[pixel] > 0; });
  const double black = std::max(in.tolerance.max_abs, 1e-6);
  bool failures_unlit_and_black = true;
  for (size_t k = 0; k < in.pixels.size(); ++k) {
    if (!in.failed[k]) continue;
    const size_t pixel = in.pixels[k];
    const Rgb& r = in.reference_values[k];
    failures_unlit_and_black = failures_unlit_and_black && n_dot_l[pixel] <= 0 &&
                               std::abs(r[0]) <= black && std::abs(r[1]) <= black && std::abs(r[2]) <= black;
  }
  const std::string not_gated =
      failures_unlit_and_black
          ? fmt::format("where N·L > 0 (the render is not gated by N·L > 0 where the reference is: all {} failing "
                        "pixels lie where N·L <= 0 and the reference is black)",
                        in.failed_count)
          : std::string("where N·L > 0 (the render is not gated by N·L > 0 where the reference is; but not every "
                        "failing pixel lies where N·L <= 0 on a black reference)");
  out.push_back(fit_of("not_gated_by_n_dot_l", not_gated, lit, failures_unlit_and_black));

  // |n|^e: e from the log ratios, where both sides are positive and |n| is not 1. The
  // factor is the same on every channel, so one ratio per pixel (of the channel sums)
  // carries it, at a third of the logarithms.
  double log_products = 0, log_length_squared = 0;
  for (size_t k = 0; k < in.pixels.size(); ++k) {
    const size_t pixel = in.pixels[k];
    if (!(length[pixel] > 0) || std::abs(length[pixel] - 1) < 1e-12) continue;
    const Rgb &q = in.render_values[k], &r = in.reference_values[k];
    const double render_sum = q[0] + q[1] + q[2], reference_sum = r[0] + r[1] + r[2];
    if (!(render_sum > 0 && reference_sum > 0)) continue;
    const double log_length = std::log(length[pixel]);
    log_products += std::log(render_sum / reference_sum) * log_length;
    log_length_squared += log_length * log_length;
  }
  if (log_length_squared > 0) {
    const double e = log_products / log_length_squared;
    const std::string what = std::abs(e - 1) < 0.05 ? "; e ≈ 1: a diffuse term"
                             : e > 1.5               ? fmt::format("; e ≈ {:.3g}: a specular lobe's exponent", e)
                                                     : "";
    out.push_back(fit_of("unnormalised_normal",
                         fmt::format("× |n|^{:.3g} (the render does not renormalise the interpolated normal{})", e,
                                     what),
                         evaluate(in, [&](size_t pixel, Rgb&, Rgb& r) {
                           if (!(length[pixel] > 0)) return false;
                           const double factor = std::pow(length[pixel], e);
                           for (double& channel : r) channel *= factor;
                           return true;
                         })));
  }
}

// ---- 5. counterfactual references ---------------------------------------------------------

void counterfactual(const FitInputs& in, const Counterfactual& what, std::vector<ConventionFit>& out) {
  const ReferenceImage* image = what.image;
  if (!image || image->width != in.reference.width || image->height != in.reference.height ||
      image->rgba.size() != in.reference.rgba.size() || image->coverage.size() != in.reference.coverage.size())
    return;
  out.push_back(fit_of(what.name, "re-rendered with " + what.detail, evaluate(in, [&](size_t pixel, Rgb&, Rgb& r) {
                         if (!image->coverage[pixel]) return false;
                         const double* p = &image->rgba[pixel * 4];
                         r = {p[0], p[1], p[2]};
                         return finite(r);
                       })));
}

// ---- 6. gamma --------------------------------------------------------------------------

double srgb_encode(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }
double srgb_decode(double x) { return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4); }

void gamma(const FitInputs& in, std::vector<ConventionFit>& out) {
  struct Curve {
    const char* name;
    const char* description;
    double (*apply)(double);
  };
  const Curve curves[] = {
      {"gamma_encoded_render",
       "encoded with gamma 2.2, x^(1/2.2) (the render applies gamma 2.2 encoding the reference lacks)",
       [](double x) { return std::pow(x, 1 / 2.2); }},
      {"gamma_decoded_render",
       "decoded with gamma 2.2, x^2.2 (the render applies gamma 2.2 decoding the reference lacks)",
       [](double x) { return std::pow(x, 2.2); }},
      {"srgb_encoded_render", "sRGB-encoded (the render applies the sRGB encoding the reference lacks)", srgb_encode},
      {"srgb_decoded_render", "sRGB-decoded (the render applies the sRGB decoding the reference lacks)", srgb_decode},
  };
  const auto explain_with = [](const Curve& curve) {
    return [&curve](size_t, Rgb&, Rgb& r) {
      for (double& channel : r) channel = curve.apply(std::max(0.0, channel));
      return true;
    };
  };
  const Curve& best = curves[best_variant(in, std::size(curves), [&](size_t i) { return explain_with(curves[i]); })];
  out.push_back(fit_of(best.name, best.description, evaluate(in, explain_with(best))));
}

// ---- 7. clamping -------------------------------------------------------------------------

void clamping(const FitInputs& in, std::vector<ConventionFit>& out) {
  out.push_back(fit_of("render_clamps", "clamped to [0, 1] (the render clamps, the reference does not)",
                       evaluate(in, [](size_t, Rgb&, Rgb& r) {
                         for (double& channel : r) channel = std::clamp(channel, 0.0, 1.0);
                         return true;
                       })));
  size_t outside = 0;
  const Tally tally = evaluate(in, [&](size_t, Rgb& q, Rgb&) {
    for (double& channel : q) {
      outside += channel < 0 || channel > 1;
      channel = std::clamp(channel, 0.0, 1.0);
    }
    return true;
  });
  out.push_back(fit_of("render_does_not_clamp",
                       fmt::format("once the render is clamped to [0, 1] (the reference clamps, the render does not: "
                                   "{} channels outside [0, 1])",
                                   outside),
                       tally, tally.failed_not_evaluated == 0 && outside > 0));
}

// ---- 8. half-pixel offset ----------------------------------------------------------------

void half_pixel_offset(const FitInputs& in, std::vector<ConventionFit>& out) {
  const ReferenceImage& reference = in.reference;
  const int width = reference.width, height = reference.height;
  constexpr std::array<std::pair<int, int>, 4> signs{{{1, 1}, {-1, 1}, {1, -1}, {-1, -1}}};
  // The reference's average over the pixel and its neighbours toward (sx, sy): bilinear
  // at the corner they share.
  const auto explain_with = [&](std::pair<int, int> sign) {
    return [&, sx = sign.first, sy = sign.second](size_t pixel, Rgb&, Rgb& r) {
      const int x = int(pixel % size_t(width)), y = int(pixel / size_t(width));
      if (x + sx < 0 || x + sx >= width || y + sy < 0 || y + sy >= height) return false;
      Rgb sum{0, 0, 0};
      for (const auto& [dx, dy] : {std::pair{0, 0}, std::pair{sx, 0}, std::pair{0, sy}, std::pair{sx, sy}}) {
        const size_t neighbour = size_t(y + dy) * width + (x + dx);
        if (!reference.coverage[neighbour]) return false;
        for (int c = 0; c < 3; ++c) sum[c] += reference.rgba[neighbour * 4 + c];
      }
      for (int c = 0; c < 3; ++c) r[c] = 0.25 * sum[c];
      return finite(r);
    };
  };
  const auto [sx, sy] = signs[best_variant(in, signs.size(), [&](size_t i) { return explain_with(signs[i]); })];
  out.push_back(fit_of("half_pixel_offset",
                       fmt::format("resampled at (x {} 0.5, y {} 0.5) (a half-pixel offset: D3D9 pixel centres)",
                                   sx > 0 ? "+" : "−", sy > 0 ? "+" : "−"),
                       evaluate(in, explain_with({sx, sy}))));
}

bool same_size(const SurfaceSamples& surface, const ReferenceImage& reference) {
  const size_t count = reference.coverage.size();
  return surface.width == reference.width && surface.height == reference.height && surface.n_dot_l.size() == count &&
         surface.n_dot_v.size() == count && surface.normal_length.size() == count;
}

// Interior pixels the render drew where exactly one of render and reference is NaN/Inf:
// what no colour convention can produce from a finite reference (or remove from it).
std::vector<size_t> nonfinite_mismatches(const Image& render, const ReferenceImage& reference,
                                         const std::vector<PixelClass>& classes) {
  std::vector<size_t> pixels;
  for (size_t pixel = 0; pixel < classes.size(); ++pixel) {
    if (classes[pixel] != PixelClass::interior || !render.coverage[pixel]) continue;
    const float* p = &render.rgba[pixel * 4];
    const double* r = &reference.rgba[pixel * 4];
    if (finite(Rgb{p[0], p[1], p[2]}) != finite(Rgb{r[0], r[1], r[2]})) pixels.push_back(pixel);
  }
  return pixels;
}

// Whether a counterfactual's image is finite exactly where the render is, at `pixels`:
// then it explains the NaN/Inf too, and may be offered beside them.
bool same_nonfinite(const Image& render, const ReferenceImage& image, const std::vector<size_t>& pixels) {
  return std::ranges::all_of(pixels, [&](size_t pixel) {
    const float* p = &render.rgba[pixel * 4];
    const double* q = &image.rgba[pixel * 4];
    return image.coverage[pixel] && finite(Rgb{p[0], p[1], p[2]}) == finite(Rgb{q[0], q[1], q[2]});
  });
}

}  // namespace

std::vector<ConventionFit> explain_difference(const Image& render, const ReferenceImage& reference,
                                              const std::vector<PixelClass>& classes,
                                              const ComparisonThresholds& thresholds,
                                              const ConventionEvidence& evidence) {
  const size_t count = size_t(reference.width) * size_t(reference.height);
  if (render.width != reference.width || render.height != reference.height || classes.size() != count ||
      render.rgba.size() != count * 4 || reference.rgba.size() != count * 4 || render.coverage.size() != count ||
      reference.coverage.size() != count)
    return {};
  const FitInputs in = fit_inputs(render, reference, classes, thresholds);
  if (in.failed_count == 0) return {};

  std::vector<ConventionFit> fits;
  constant_factor(in, evidence.parameters, fits);
  if (evidence.surface && same_size(*evidence.surface, reference)) surface_explanations(in, *evidence.surface, fits);
  for (const Counterfactual& what : evidence.counterfactuals) counterfactual(in, what, fits);
  gamma(in, fits);
  clamping(in, fits);
  half_pixel_offset(in, fits);
  // NaN/Inf the reference does not have (or the reverse): a convention fitted on the
  // finite pixels around them would be offered for a cell it does not explain. Only a
  // counterfactual with the same non-finite pixels stays.
  if (const std::vector<size_t> mismatches = nonfinite_mismatches(render, reference, classes); !mismatches.empty())
    std::erase_if(fits, [&](const ConventionFit& fit) {
      const auto same = std::ranges::find(evidence.counterfactuals, fit.name, &Counterfactual::name);
      return same == evidence.counterfactuals.end() || !same_nonfinite(render, *same->image, mismatches);
    });
  std::stable_sort(fits.begin(), fits.end(), better);
  return fits;
}

std::string describe(const ConventionFit& fit) {
  if (fit.fits) return fmt::format("matches the reference {} to {}", fit.description, short_number(fit.residual));
  return fmt::format("{} fits only to {} (incomplete)", fit.description, short_number(fit.residual));
}

}  // namespace shaderbed
