// explain_difference(): for each explanation, a synthetic reference with the convention
// planted in the render is explained by it, ranked first; the same reference with a
// different planted error is not. Then the edges: nothing to explain, missing evidence,
// failing pixels an explanation would skip, the line describe() writes, and the real
// reference (render_surface, Perturbation) end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "compare/ConventionFit.h"
#include "compare/SurfaceSamples.h"
#include "reference/Reference.h"
#include "reference/Surface.h"

namespace shaderbed {
namespace {

constexpr double kPi = std::numbers::pi;
using Rgb = std::array<double, 3>;

// A sphere seen head-on (orthographic) as a disc, lit from the side so the terminator
// crosses it: per pixel the unit normal, N·L, N·V and a tessellation-like |n| < 1 that
// dips between "vertices" every 6 pixels.
struct Geometry {
  int size = 0;
  std::vector<uint8_t> covered;
  std::vector<glm::dvec3> normal;
  SurfaceSamples surface;
};

const glm::dvec3 kLight = glm::normalize(glm::dvec3(0.8, 0.3, 0.2));
const glm::dvec3 kEye{0, 0, 1};
const glm::dvec3 kHalf = glm::normalize(kLight + kEye);
const Rgb kDiffuse{0.8, 0.6, 0.4};

Geometry disc_geometry(int size = 64) {
  const double centre = size / 2.0, radius = size * 0.4;
  const size_t count = size_t(size) * size;
  Geometry g{size, std::vector<uint8_t>(count, 0), std::vector<glm::dvec3>(count, glm::dvec3(0.0)),
             SurfaceSamples{size, size, std::vector<double>(count, 0.0), std::vector<double>(count, 0.0),
                            std::vector<double>(count, 0.0)}};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5 - centre) / radius, v = (y + 0.5 - centre) / radius;
      if (u * u + v * v > 1) continue;
      const size_t i = size_t(y) * size + x;
      const glm::dvec3 n(u, -v, std::sqrt(std::max(0.0, 1 - u * u - v * v)));
      g.covered[i] = 1;
      g.normal[i] = n;
      g.surface.n_dot_l[i] = glm::dot(n, kLight);
      g.surface.n_dot_v[i] = glm::dot(n, kEye);
      const double sx = std::sin(kPi * (x + 0.5) / 6), sy = std::sin(kPi * (y + 0.5) / 6);
      g.surface.normal_length[i] = 1 - 0.08 * sx * sx * sy * sy;
    }
  return g;
}

// Lambert and an ungated Blinn-Phong-like lobe (nonzero on part of the unlit side).
double n_dot_l(const Geometry& g, size_t i) { return g.surface.n_dot_l[i]; }
Rgb lambert(const Geometry& g, size_t i) {
  const double f = std::max(0.0, n_dot_l(g, i));
  return {kDiffuse[0] * f, kDiffuse[1] * f, kDiffuse[2] * f};
}
double lobe(const Geometry& g, size_t i) { return 0.5 * std::pow(std::max(0.0, glm::dot(g.normal[i], kHalf)), 8); }
Rgb plus(Rgb a, double s) { return {a[0] + s, a[1] + s, a[2] + s}; }
Rgb times(Rgb a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

ReferenceImage reference_of(const Geometry& g, const std::function<Rgb(size_t)>& shade) {
  const size_t count = g.covered.size();
  ReferenceImage ref{g.size, g.size, std::vector<double>(count * 4, 0.0), g.covered};
  for (size_t i = 0; i < count; ++i) {
    if (!g.covered[i]) continue;
    const Rgb c = shade(i);
    for (int k = 0; k < 3; ++k) ref.rgba[i * 4 + k] = c[k];
    ref.rgba[i * 4 + 3] = 1;
  }
  return ref;
}

// A float render with the reference's coverage: planted(pixel, reference colour).
Image render_of(const ReferenceImage& ref, const std::function<Rgb(size_t, const Rgb&)>& planted) {
  Image im(ref.width, ref.height);
  im.coverage = ref.coverage;
  for (size_t i = 0; i < ref.coverage.size(); ++i) {
    if (!ref.coverage[i]) continue;
    const Rgb c = planted(i, {ref.rgba[i * 4], ref.rgba[i * 4 + 1], ref.rgba[i * 4 + 2]});
    for (int k = 0; k < 3; ++k) im.rgba[i * 4 + k] = float(c[k]);
    im.rgba[i * 4 + 3] = 1;
  }
  return im;
}

const ComparisonThresholds kFitThresholds{.interior_max_abs = 1e-4, .silhouette_max_abs = 1e-4};

struct Explained {
  std::vector<ConventionFit> fits;
  const ConventionFit* find(const std::string& name) const {
    for (const ConventionFit& fit : fits)
      if (fit.name == name) return &fit;
    return nullptr;
  }
  std::string listing() const {
    std::string text;
    for (const ConventionFit& fit : fits) text += fit.name + ": " + describe(fit) + "\n";
    return text;
  }
};

Explained explain(const Image& render, const ReferenceImage& ref, const ConventionEvidence& evidence = {},
                  const ComparisonThresholds& thresholds = kFitThresholds) {
  return {explain_difference(render, ref, classify_pixels(ref), thresholds, evidence)};
}

// `name` fits and is ranked first.
void expect_first(const Explained& explained, const std::string& name) {
  ASSERT_FALSE(explained.fits.empty());
  EXPECT_EQ(explained.fits.front().name, name) << explained.listing();
  EXPECT_TRUE(explained.fits.front().fits) << explained.listing();
  EXPECT_GT(explained.fits.front().pixels, 1000u);
}

// `name` is listed and does not fit.
void expect_no_fit(const Explained& explained, const std::string& name) {
  const ConventionFit* fit = explained.find(name);
  ASSERT_NE(fit, nullptr) << name << " missing:\n" << explained.listing();
  EXPECT_FALSE(fit->fits) << explained.listing();
}

class ConventionFitTest : public ::testing::Test {
 protected:
  Geometry g = disc_geometry();
  ReferenceImage lambert_ref = reference_of(g, [&](size_t i) { return lambert(g, i); });
  ConventionEvidence with_surface{.surface = &g.surface};
  Image scaled_by_pi = render_of(lambert_ref, [](size_t, const Rgb& r) { return times(r, kPi); });
};

TEST_F(ConventionFitTest, ConstantFactorNamesPi) {
  const Explained explained = explain(scaled_by_pi, lambert_ref, with_surface);
  expect_first(explained, "constant_factor");
  EXPECT_EQ(explained.fits.front().description, "× π (1/π normalisation in the reference only)");
  EXPECT_LT(explained.fits.front().residual, 1e-5);
  EXPECT_TRUE(describe(explained.fits.front()).starts_with("matches the reference × π (1/π normalisation"));
}

TEST_F(ConventionFitTest, ConstantFactorNamesAParametersNormalisation) {
  const Image render = render_of(lambert_ref, [](size_t, const Rgb& r) { return times(r, 9 / (2 * kPi)); });
  const Explained explained =
      explain(render, lambert_ref, {.surface = &g.surface, .parameters = {{"power", 7}, {"roughness", 0.3}}});
  expect_first(explained, "constant_factor");
  EXPECT_EQ(explained.fits.front().description,
            "× (power+2)/2π with power = 7 (energy-normalised Phong lobe in the render only)");
  const Image inverse = render_of(lambert_ref, [](size_t, const Rgb& r) { return times(r, 8 * kPi / 15); });
  const Explained inverse_explained = explain(inverse, lambert_ref, {.parameters = {{"n", 7}}});
  expect_first(inverse_explained, "constant_factor");
  EXPECT_EQ(inverse_explained.fits.front().description,
            "× 8π/(n+8) with n = 7 (energy-normalised Blinn-Phong lobe in the reference only)");
}

TEST_F(ConventionFitTest, ConstantFactorUnnamedAndNotFittingAnExtraNDotL) {
  const Image render =
      render_of(lambert_ref, [&](size_t i, const Rgb& r) { return times(r, std::max(0.0, n_dot_l(g, i))); });
  const Explained explained = explain(render, lambert_ref, with_surface);
  expect_no_fit(explained, "constant_factor");
  EXPECT_TRUE(explained.find("constant_factor")->description.starts_with("× 0."));
  EXPECT_TRUE(describe(*explained.find("constant_factor")).ends_with("(incomplete)"));
}

TEST_F(ConventionFitTest, ExtraNDotL) {
  const Image render =
      render_of(lambert_ref, [&](size_t i, const Rgb& r) { return times(r, std::max(0.0, n_dot_l(g, i))); });
  expect_first(explain(render, lambert_ref, with_surface), "extra_n_dot_l");
  expect_no_fit(explain(scaled_by_pi, lambert_ref, with_surface), "extra_n_dot_l");
}

TEST_F(ConventionFitTest, MissingNDotL) {
  // The render shades the diffuse colour on the lit side without the cosine.
  const Image render =
      render_of(lambert_ref, [&](size_t i, const Rgb&) { return n_dot_l(g, i) > 0 ? kDiffuse : Rgb{0, 0, 0}; });
  expect_first(explain(render, lambert_ref, with_surface), "missing_n_dot_l");
  expect_no_fit(explain(scaled_by_pi, lambert_ref, with_surface), "missing_n_dot_l");
}

// The division skips pixels with N·L <= 0; a render failing there is not explained by it.
TEST_F(ConventionFitTest, MissingNDotLDoesNotSkipThePixelsItCannotDivide) {
  const Image render = render_of(lambert_ref, [&](size_t, const Rgb&) { return kDiffuse; });  // not gated either
  const Explained explained = explain(render, lambert_ref, with_surface);
  expect_no_fit(explained, "missing_n_dot_l");
  EXPECT_LT(explained.find("missing_n_dot_l")->residual, 1e-6);  // exact where it can divide, yet no fit
}

TEST_F(ConventionFitTest, GatedByNDotL) {
  // Reference: ungated specular lobe (as the book's Phong); render gates it.
  const ReferenceImage ref = reference_of(g, [&](size_t i) { return plus(lambert(g, i), lobe(g, i)); });
  const Image render =
      render_of(ref, [&](size_t i, const Rgb& r) { return n_dot_l(g, i) > 0 ? r : Rgb{0, 0, 0}; });
  expect_first(explain(render, ref, with_surface), "gated_by_n_dot_l");
  expect_no_fit(explain(render_of(ref, [](size_t, const Rgb& r) { return times(r, 1.1); }), ref, with_surface),
                "gated_by_n_dot_l");
}

TEST_F(ConventionFitTest, NotGatedByNDotL) {
  // Reference: gated lobe; render: ungated, so light leaks onto the unlit side.
  const ReferenceImage ref =
      reference_of(g, [&](size_t i) { return plus(lambert(g, i), n_dot_l(g, i) > 0 ? lobe(g, i) : 0.0); });
  const Image render = render_of(ref, [&](size_t i, const Rgb&) { return plus(lambert(g, i), lobe(g, i)); });
  const Explained explained = explain(render, ref, with_surface);
  expect_first(explained, "not_gated_by_n_dot_l");
  EXPECT_NE(explained.fits.front().description.find("failing pixels lie where N·L <= 0"), std::string::npos);
  expect_no_fit(explain(render_of(ref, [](size_t, const Rgb& r) { return times(r, kPi); }), ref, with_surface),
                "not_gated_by_n_dot_l");
  // Failing where N·L <= 0 but on a lit reference (an ambient term): not this explanation.
  const ReferenceImage ambient = reference_of(g, [&](size_t i) { return plus(lambert(g, i), 0.1); });
  const Image extra = render_of(ambient, [&](size_t i, const Rgb& r) { return n_dot_l(g, i) > 0 ? r : plus(r, 0.2); });
  expect_no_fit(explain(extra, ambient, with_surface), "not_gated_by_n_dot_l");
}

TEST_F(ConventionFitTest, UnnormalisedNormalDiffuse) {
  const Image render =
      render_of(lambert_ref, [&](size_t i, const Rgb& r) { return times(r, g.surface.normal_length[i]); });
  const Explained explained = explain(render, lambert_ref, with_surface);
  expect_first(explained, "unnormalised_normal");
  EXPECT_NE(explained.fits.front().description.find("|n|^1 "), std::string::npos) << explained.listing();
  EXPECT_NE(explained.fits.front().description.find("a diffuse term"), std::string::npos);
  expect_no_fit(explain(scaled_by_pi, lambert_ref, with_surface), "unnormalised_normal");
}

TEST_F(ConventionFitTest, UnnormalisedNormalSpecularExponent) {
  const ReferenceImage ref = reference_of(g, [&](size_t i) { return Rgb{lobe(g, i), lobe(g, i), lobe(g, i)}; });
  const Image render =
      render_of(ref, [&](size_t i, const Rgb& r) { return times(r, std::pow(g.surface.normal_length[i], 8)); });
  const Explained explained = explain(render, ref, with_surface);
  expect_first(explained, "unnormalised_normal");
  EXPECT_NE(explained.fits.front().description.find("|n|^8 "), std::string::npos) << explained.listing();
}

TEST_F(ConventionFitTest, Counterfactuals) {
  const ReferenceImage negated_light =
      reference_of(g, [&](size_t i) { return times(kDiffuse, std::max(0.0, -n_dot_l(g, i))); });
  const ReferenceImage negated_eye = reference_of(g, [&](size_t i) { return plus(lambert(g, i), 0.01); });
  const Counterfactual counterfactuals[] = {
      {"negated_light", "the light vector negated (L → −L)", &negated_light},
      {"negated_eye", "the eye vector negated (V → −V)", &negated_eye},
  };
  const ConventionEvidence evidence{.surface = &g.surface, .counterfactuals = counterfactuals};
  const Image render = render_of(lambert_ref, [&](size_t i, const Rgb&) {
    return Rgb{negated_light.rgba[i * 4], negated_light.rgba[i * 4 + 1], negated_light.rgba[i * 4 + 2]};
  });
  const Explained explained = explain(render, lambert_ref, evidence);
  expect_first(explained, "negated_light");
  EXPECT_TRUE(describe(explained.fits.front())
                  .starts_with("matches the reference re-rendered with the light vector negated (L → −L) to "));
  expect_no_fit(explained, "negated_eye");
  const Explained scaled = explain(scaled_by_pi, lambert_ref, evidence);
  expect_no_fit(scaled, "negated_light");
  expect_no_fit(scaled, "negated_eye");
  // Without the images (or with a wrong size) they are absent.
  EXPECT_EQ(explain(render, lambert_ref, with_surface).find("negated_light"), nullptr);
  const ReferenceImage small{2, 2, std::vector<double>(16, 0.0), std::vector<uint8_t>(4, 1)};
  const Counterfactual wrong_size[] = {{"negated_light", "the light negated", &small}};
  EXPECT_EQ(explain(render, lambert_ref, {.counterfactuals = wrong_size}).find("negated_light"), nullptr);
}

double srgb_encode(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }
double srgb_decode(double x) { return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4); }

TEST_F(ConventionFitTest, Gamma) {
  const ReferenceImage ref = reference_of(g, [&](size_t i) { return plus(lambert(g, i), 0.05); });
  const std::pair<const char*, double (*)(double)> curves[] = {
      {"gamma_encoded_render", [](double x) { return std::pow(x, 1 / 2.2); }},
      {"gamma_decoded_render", [](double x) { return std::pow(x, 2.2); }},
      {"srgb_encoded_render", srgb_encode},
      {"srgb_decoded_render", srgb_decode},
  };
  for (const auto& [name, curve] : curves) {
    SCOPED_TRACE(name);
    const Image render =
        render_of(ref, [&](size_t, const Rgb& r) { return Rgb{curve(r[0]), curve(r[1]), curve(r[2])}; });
    const Explained explained = explain(render, ref, with_surface);
    expect_first(explained, name);
    EXPECT_NE(explained.fits.front().description.find("the render applies"), std::string::npos);
  }
  // Scaled by π: the family's best variant is listed, and does not fit.
  const Explained scaled = explain(render_of(ref, [](size_t, const Rgb& r) { return times(r, kPi); }), ref);
  for (const ConventionFit& fit : scaled.fits)
    if (fit.name.find("gamma") != std::string::npos || fit.name.find("srgb") != std::string::npos) {
      EXPECT_FALSE(fit.fits) << scaled.listing();
    }
}

TEST_F(ConventionFitTest, RenderClamps) {
  const ReferenceImage bright = reference_of(g, [&](size_t i) { return times(lambert(g, i), 1.6); });
  const Image render = render_of(bright, [](size_t, const Rgb& r) {
    return Rgb{std::min(r[0], 1.0), std::min(r[1], 1.0), std::min(r[2], 1.0)};
  });
  expect_first(explain(render, bright, with_surface), "render_clamps");
  expect_no_fit(explain(render_of(bright, [](size_t, const Rgb& r) { return times(r, 0.9); }), bright, with_surface),
                "render_clamps");
}

TEST_F(ConventionFitTest, RenderDoesNotClamp) {
  const ReferenceImage clamped = reference_of(g, [&](size_t i) {
    const Rgb c = times(lambert(g, i), 1.6);
    return Rgb{std::min(c[0], 1.0), std::min(c[1], 1.0), std::min(c[2], 1.0)};
  });
  const Image render = render_of(clamped, [&](size_t i, const Rgb&) { return times(lambert(g, i), 1.6); });
  const Explained explained = explain(render, clamped, with_surface);
  expect_first(explained, "render_does_not_clamp");
  EXPECT_NE(explained.fits.front().description.find("channels outside [0, 1]"), std::string::npos);
  expect_no_fit(explain(render_of(clamped, [](size_t, const Rgb& r) { return times(r, 0.9); }), clamped, with_surface),
                "render_does_not_clamp");
}

TEST_F(ConventionFitTest, HalfPixelOffset) {
  const int w = lambert_ref.width;
  // The render sees the reference half a pixel right and down (the corner between four centres).
  const Image render = render_of(lambert_ref, [&](size_t i, const Rgb&) {
    Rgb sum{0, 0, 0};
    for (size_t j : {i, i + 1, i + size_t(w), i + size_t(w) + 1})
      for (int c = 0; c < 3; ++c) sum[c] += lambert_ref.rgba[j * 4 + c];
    return times(sum, 0.25);
  });
  const Explained explained = explain(render, lambert_ref, with_surface);
  expect_first(explained, "half_pixel_offset");
  EXPECT_NE(explained.fits.front().description.find("(x + 0.5, y + 0.5)"), std::string::npos);
  expect_no_fit(explain(scaled_by_pi, lambert_ref, with_surface), "half_pixel_offset");
}

// The fitting ones first, each group by residual.
TEST_F(ConventionFitTest, SortedFittingFirstThenByResidual) {
  const Explained explained = explain(scaled_by_pi, lambert_ref, with_surface);
  ASSERT_GT(explained.fits.size(), 8u);
  for (size_t i = 1; i < explained.fits.size(); ++i) {
    const ConventionFit &a = explained.fits[i - 1], &b = explained.fits[i];
    EXPECT_TRUE(a.fits >= b.fits);
    if (a.fits == b.fits) {
      EXPECT_LE(a.residual, b.residual);
    }
  }
}

// A render within tolerance has nothing to explain: the list is empty (so nothing "fits"
// trivially). So is a render that fails only on non-finite or coverage.
TEST_F(ConventionFitTest, NothingToExplainGivesAnEmptyList) {
  const Image same = render_of(lambert_ref, [](size_t, const Rgb& r) { return plus(r, 5e-5); });
  EXPECT_TRUE(explain(same, lambert_ref, with_surface).fits.empty());
  Image nan = render_of(lambert_ref, [](size_t, const Rgb& r) { return r; });
  nan.pixel(32, 32)[0] = NAN;
  nan.coverage[nan.index(30, 30)] = 0;
  EXPECT_TRUE(explain(nan, lambert_ref, with_surface).fits.empty());
  Image wrong_size(8, 8);
  EXPECT_TRUE(explain(wrong_size, lambert_ref, with_surface).fits.empty());
}

// NaN/Inf where the reference is finite: × π fits the finite rest, but it is not offered
// beside pixels it cannot produce; a counterfactual with the same NaN/Inf is.
TEST_F(ConventionFitTest, NoFitOfferedBesideNonFinitePixels) {
  Image render = scaled_by_pi;
  for (int x = 20; x < 30; ++x) render.pixel(x, 32)[1] = NAN;
  render.pixel(40, 40)[0] = INFINITY;
  EXPECT_TRUE(explain(render, lambert_ref, with_surface).fits.empty()) << explain(render, lambert_ref, with_surface).listing();
  ReferenceImage same = reference_of(g, [&](size_t i) { return times(lambert(g, i), kPi); });
  ReferenceImage elsewhere = same;
  for (int x = 20; x < 30; ++x) same.rgba[(size_t(32) * g.size + x) * 4 + 1] = NAN;
  same.rgba[(size_t(40) * g.size + 40) * 4] = INFINITY;
  elsewhere.rgba[(size_t(10) * g.size + 32) * 4] = NAN;
  const Counterfactual counterfactuals[] = {{"same_nonfinite", "NaN/Inf where the render has them", &same},
                                            {"other_nonfinite", "NaN elsewhere", &elsewhere}};
  const Explained explained = explain(render, lambert_ref, {.surface = &g.surface, .counterfactuals = counterfactuals});
  ASSERT_EQ(explained.fits.size(), 1u) << explained.listing();
  expect_first(explained, "same_nonfinite");
  // Without NaN/Inf the same render is explained as before.
  expect_first(explain(scaled_by_pi, lambert_ref, with_surface), "constant_factor");
}

// The relative part of the tolerance counts: a 0.1% error passes with max_rel = 2e-3.
TEST_F(ConventionFitTest, RelativeToleranceCounts) {
  const Image render = render_of(lambert_ref, [](size_t, const Rgb& r) { return times(r, 1.001); });
  EXPECT_FALSE(explain(render, lambert_ref, with_surface).fits.empty());
  EXPECT_TRUE(explain(render, lambert_ref, with_surface,
                      {.interior_max_abs = 1e-4, .silhouette_max_abs = 1e-4, .interior_max_rel = 2e-3})
                  .fits.empty());
}

TEST_F(ConventionFitTest, WithoutSurfaceSamplesTheirExplanationsAreAbsent) {
  const Explained explained = explain(scaled_by_pi, lambert_ref);
  for (const char* name : {"extra_n_dot_l", "missing_n_dot_l", "gated_by_n_dot_l", "not_gated_by_n_dot_l",
                           "unnormalised_normal"})
    EXPECT_EQ(explained.find(name), nullptr) << name;
  EXPECT_NE(explained.find("constant_factor"), nullptr);
  EXPECT_NE(explained.find("half_pixel_offset"), nullptr);
  EXPECT_NE(explained.find("render_clamps"), nullptr);
}

TEST(ConventionFitDescribe, Lines) {
  EXPECT_EQ(describe({"constant_factor", "× π (1/π normalisation)", 2e-6, 1e-6, 100, true}),
            "matches the reference × π (1/π normalisation) to 2e-6");
  EXPECT_EQ(describe({"constant_factor", "× 1.73", 0.04, 0.01, 100, false}), "× 1.73 fits only to 0.04 (incomplete)");
  EXPECT_EQ(describe({"x", "× 2", 3.5e-7, 0, 1, true}), "matches the reference × 2 to 3.5e-7");
  EXPECT_EQ(describe({"x", "× 2", 0, 0, 1, true}), "matches the reference × 2 to 0");
  EXPECT_EQ(describe({"x", "× 2", 250, 0, 1, false}), "× 2 fits only to 2.5e2 (incomplete)");
}

// ---- The real reference: render_surface + Perturbation as the runner will use them ----------

reference::Mesh coarse_sphere(int slices, int stacks) {
  reference::Mesh mesh;
  for (int j = 0; j <= stacks; ++j) {
    const double theta = kPi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double phi = 2 * kPi * i / slices;
      const glm::dvec3 p(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.vertices.push_back({p, p, {-std::sin(phi), 0, std::cos(phi)}, {double(i) / slices, double(j) / stacks}});
    }
  }
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const auto a = static_cast<uint32_t>(j * (slices + 1) + i), b = a + 1, c = a + slices + 1, d = c + 1;
      for (uint32_t index : {a, b, c, b, d, c}) mesh.indices.push_back(index);
    }
  return mesh;
}

ReferenceImage to_reference_image(const reference::Framebuffer& fb) {
  return {fb.width, fb.height, fb.rgba, fb.coverage};
}

Image to_render(const reference::Framebuffer& fb) {
  Image im(fb.width, fb.height);
  for (size_t i = 0; i < fb.rgba.size(); ++i) im.rgba[i] = float(fb.rgba[i]);
  im.coverage = fb.coverage;
  return im;
}

class ConventionFitOnTheReference : public ::testing::Test {
 protected:
  void SetUp() override {
    scene.mesh = coarse_sphere(12, 8);
    scene.width = scene.height = 128;
    scene.camera.eye = {0, 0, -5};
    scene.lights.direction = glm::normalize(glm::dvec3(-1, 1, 0.3));
    auto surface = reference::render_surface(scene);
    ASSERT_TRUE(surface) << surface.error();
    samples = surface_samples(*surface);
    reference = to_reference_image(rendered({}));
  }

  reference::Framebuffer rendered(const reference::Perturbation& perturbation) {
    auto image = reference::render(scene, "phong", reference::Mode::per_pixel, params, perturbation);
    EXPECT_TRUE(image) << image.error();
    return image ? *image : reference::Framebuffer{};
  }

  reference::Scene scene;
  const reference::Params params{{"diffuse", {0.6, 0.5, 0.4}}, {"specular", {0.4, 0.4, 0.4}}, {"power", {7}}};
  SurfaceSamples samples;
  ReferenceImage reference;
};

TEST_F(ConventionFitOnTheReference, NamesThePerturbationThatMadeTheRender) {
  const ReferenceImage negated_light = to_reference_image(rendered({.negate_light = true}));
  const ReferenceImage negated_eye = to_reference_image(rendered({.negate_eye = true}));
  const ReferenceImage unnormalised = to_reference_image(rendered({.unnormalised_normal = true}));
  const ReferenceImage interpolated = to_reference_image(rendered({.interpolated_light_eye = true}));
  const ReferenceImage faceted = to_reference_image(rendered({.faceted_normal = true}));
  const Counterfactual counterfactuals[] = {
      {"negated_light", "the light vector negated (L → −L)", &negated_light},
      {"negated_eye", "the eye vector negated (V → −V)", &negated_eye},
      {"unnormalised_normal_image", "the interpolated normal not renormalised", &unnormalised},
      {"interpolated_light_eye", "L and V normalised per vertex and interpolated", &interpolated},
      {"faceted_normal", "the flat facet normal", &faceted},
  };
  const ConventionEvidence evidence{.surface = &samples, .counterfactuals = counterfactuals,
                                    .parameters = {{"power", 7}}};
  for (const auto* planted : {&negated_light, &negated_eye, &unnormalised, &interpolated, &faceted}) {
    const Image render = to_render({planted->width, planted->height, planted->rgba, planted->coverage});
    const Explained explained = explain(render, reference, evidence);
    ASSERT_FALSE(explained.fits.empty());
    const ConventionFit& first = explained.fits.front();
    EXPECT_TRUE(first.fits) << explained.listing();
    const std::string expected = planted == &negated_light  ? "negated_light"
                                 : planted == &negated_eye  ? "negated_eye"
                                 : planted == &interpolated ? "interpolated_light_eye"
                                 : planted == &faceted      ? "faceted_normal"
                                                            : "unnormalised_normal_image";
    EXPECT_EQ(first.name, expected) << explained.listing();
    EXPECT_TRUE(explained.find(expected)->fits);
    for (const Counterfactual& other : counterfactuals)
      if (other.name != expected) {
        EXPECT_FALSE(explained.find(other.name)->fits) << explained.listing();
      }
  }
  // π on the real reference: the plain factor, named.
  Image scaled = to_render({reference.width, reference.height, reference.rgba, reference.coverage});
  for (size_t i = 0; i < scaled.rgba.size(); ++i)
    if (i % 4 != 3) scaled.rgba[i] = float(reference.rgba[i] * kPi);
  const Explained explained = explain(scaled, reference, evidence);
  expect_first(explained, "constant_factor");
  EXPECT_TRUE(describe(explained.fits.front()).starts_with("matches the reference × π (1/π normalisation"))
      << explained.listing();
}

TEST_F(ConventionFitOnTheReference, SurfaceSamplesFollowTheSurface) {
  const size_t count = size_t(scene.width) * scene.height;
  ASSERT_EQ(samples.n_dot_l.size(), count);
  double shortest = 1;
  for (size_t i = 0; i < count; ++i) {
    if (!reference.coverage[i]) {
      EXPECT_EQ(samples.normal_length[i], 0.0);
      continue;
    }
    EXPECT_GE(samples.n_dot_l[i], -1.0);
    EXPECT_LE(samples.n_dot_l[i], 1.0);
    shortest = std::min(shortest, samples.normal_length[i]);
  }
  EXPECT_LT(shortest, 0.98);
  // The middle of the sphere faces the eye.
  EXPECT_GT(samples.n_dot_v[size_t(scene.height / 2) * scene.width + scene.width / 2], 0.99);
}


}  // namespace
}  // namespace shaderbed
