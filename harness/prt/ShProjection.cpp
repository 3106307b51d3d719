#include "prt/ShProjection.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include <fmt/format.h>

#include "prt/ProbeFile.h"
#include "prt/RgbValues.h"
#include "prt/ShLight.h"
#include "sh/Basis.h"
#include "sh/EnvironmentMap.h"
#include "sh/Lights.h"
#include "sh/Projection.h"

namespace shaderbed {
namespace {

// The book's Fig. 8.14 worked example as printed (5 bands, 100 x 100 jittered samples),
// i = 0..24. Its zeros by symmetry (i = 5, 7, 10, ...) are Monte Carlo noise.
constexpr double kBookPrinted[25] = {
    0.399249,  -0.210748, 0.286867,  0.282772,  -0.315302,  //
    -0.000398, 0.131591,  0.000977,  0.093585,  -0.249934,  //
    -0.000721, 0.122896,  0.304576,  -0.164276, -0.000615,  //
    -0.091265, -0.101271, -0.000139, 0.132715,  -0.000166,  //
    0.344469,  0.001542,  -0.041332, -0.000069, -0.153648};

// Projection onto a grid x grid jittered set (Sampling.h) in slices of samples, so the basis
// table stays small at a million samples; one slice (grid <= 128) is exactly sh::project.
template <class T, class F>
std::vector<T> jittered_projection(const F& f, int bands, int grid, uint64_t seed) {
  constexpr size_t kSlice = 16384;
  const std::vector<sh::Sample> samples = sh::jittered_samples(grid, seed);
  std::vector<T> sum(size_t(sh::coefficient_count(bands)), T(0.0));
  for (size_t first = 0; first < samples.size(); first += kSlice) {
    const sh::SampleSet slice(std::vector<sh::Sample>(samples.begin() + std::ptrdiff_t(first),
                                                      samples.begin() + std::ptrdiff_t(std::min(samples.size(), first + kSlice))),
                              bands);
    std::vector<T> part;
    if constexpr (std::is_same_v<T, double>) part = sh::project(f, slice);
    else part = sh::project_rgb(f, slice);
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += part[i];
  }
  return sum;
}

// Fills the description, the method and the coefficients of a light that is not the book's.
std::expected<void, std::string> project_light(ShProjection& p) {
  const ShProjectionRequest& a = p.request;
  const bool sampled = !a.exact_only;
  const glm::dvec3 white(1.0);
  const glm::dvec3 scene_direction(a.direction[0], a.direction[1], a.direction[2]);
  if (a.light == "directional" || (a.light == "cone" && a.radius < sh::ConeLight::directional_below)) {
    auto light = sh::make_directional_light(sh::to_sh_frame(scene_direction), white);
    if (!light) return std::unexpected(light.error());
    p.description = fmt::format("a directional light (D3DXSHEvalDirectionalLight) toward ({:g}, {:g}, {:g}) in the scene, "
                                "colour 1{}",
                                a.direction[0], a.direction[1], a.direction[2],
                                a.light == "cone" ? fmt::format(" (a cone of radius {:g} < {:g} is one)", a.radius,
                                                                sh::ConeLight::directional_below)
                                                  : "");
    p.exact_method = fmt::format("exact: pi / N({}) y(d) with D3DX's N({}) = {:g}; a delta has no sampled projection",
                                 a.bands, a.bands, sh::directional_light_normalisation(a.bands));
    p.exact_rgb = light->coefficients(a.bands);
    return {};
  }
  p.has_jittered = sampled;
  if (a.light == "cone") {
    auto light = sh::make_cone_light(sh::to_sh_frame(scene_direction), a.radius, white);
    if (!light) return std::unexpected(light.error());
    const sh::ConeLight cone = *light;
    p.description = fmt::format("a cone light (D3DXSHEvalConeLight) toward ({:g}, {:g}, {:g}) in the scene, half-angle "
                                "{:g} rad, radiance {:.6g} inside",
                                a.direction[0], a.direction[1], a.direction[2], a.radius, cone.radiance().r);
    p.exact_method = "exact: the cap's zonal integral in closed form";
    if (sampled)
      p.jittered_rgb = jittered_projection<glm::dvec3>([&](const glm::dvec3& d) { return cone(d); }, a.bands, a.grid, a.seed);
    p.exact_rgb = cone.coefficients(a.bands);
  } else if (a.light == "sky") {
    const sh::SkyLight sky;
    p.description = "the analytic sky (docs/sh.md: zenith, horizon and ground colours, a sun 40 degrees up)";
    p.exact_method = "exact: zonal polynomials integrated in closed form";
    if (sampled)
      p.jittered_rgb = jittered_projection<glm::dvec3>([&](const glm::dvec3& d) { return sky(d); }, a.bands, a.grid, a.seed);
    p.exact_rgb = sky.coefficients(a.bands);
  } else {   // probe
    if (a.probe.empty()) return std::unexpected("--light probe needs --probe FILE (an .hdr or .exr environment map)");
    auto map = read_probe(a.probe, a.mapping == "angular" ? sh::MapLayout::angular : sh::MapLayout::latlong);
    if (!map) return std::unexpected(naming_file(a.probe, map.error().message));
    p.description = fmt::format("the environment map {} ({} x {}, {})", a.probe, map->width(), map->height(), a.mapping);
    p.exact_method = fmt::format("exact: Gauss-Legendre {} x {} (the run engine's rule; a bilinear map is not band-limited)",
                                 kExactQuadratureTheta, kExactQuadraturePhi);
    const auto lookup = [&](const glm::dvec3& d) { return map->lookup(d); };
    if (sampled) p.jittered_rgb = jittered_projection<glm::dvec3>(lookup, a.bands, a.grid, a.seed);
    p.exact_rgb = sh::project_rgb(lookup, sh::SampleSet(sh::gauss_legendre_samples(kExactQuadratureTheta,
                                                                                   kExactQuadraturePhi),
                                                        a.bands));
  }
  return {};
}

void keep_largest(ShProjection::Largest& largest, double value, size_t i) {
  if (value > largest.value) largest = {value, i};
}

}  // namespace

std::expected<ShProjection, std::string> project_sh_light(const ShProjectionRequest& request) {
  ShProjection p{.request = request};
  const ShProjectionRequest& a = p.request;
  if (a.light == "book") {
    p.scalar = true;
    p.has_jittered = !a.exact_only;
    p.description = "the book's test function (Eq. 13 with the code's 5 cos(theta), Figs. 8.13 and 8.14)";
    p.exact_method = "exact: its two zonal lobes integrated in closed form";
    if (p.has_jittered)
      p.jittered_scalar = jittered_projection<double>([](const glm::dvec3& d) { return sh::book_test_function(d); }, a.bands,
                                                      a.grid, a.seed);
    p.exact_scalar = sh::book_test_coefficients_exact(a.bands);
  } else if (auto made = project_light(p); !made) {
    return std::unexpected(made.error());
  }

  // The largest differences and where they are.
  const size_t n = size_t(sh::coefficient_count(a.bands));
  if (p.scalar) p.book.assign(kBookPrinted, kBookPrinted + std::min<size_t>(n, 25));
  for (size_t i = 0; i < n; ++i) {
    if (p.has_jittered)
      keep_largest(p.jittered_vs_exact,
                   p.scalar ? std::abs(p.jittered_scalar[i] - p.exact_scalar[i])
                            : max_component(p.jittered_rgb[i] - p.exact_rgb[i]),
                   i);
    if (i < p.book.size()) {
      keep_largest(p.book_vs_exact, std::abs(p.book[i] - p.exact_scalar[i]), i);
      if (p.has_jittered) keep_largest(p.book_vs_jittered, std::abs(p.book[i] - p.jittered_scalar[i]), i);
    }
  }
  return p;
}

}  // namespace shaderbed
