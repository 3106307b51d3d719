#include "prt/ShLight.h"

#include "prt/ProbeFile.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

#include "sh/Basis.h"
#include "sh/EnvironmentMap.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Rotation.h"
#include "sh/Sampling.h"
#include "sh/Transfer.h"

namespace shaderbed {
namespace {

glm::dvec3 to_sh(const glm::dvec3& v) { return sh::to_sh_frame(v); }

// The exact integrals of the lights that are not deltas: a product Gauss-Legendre rule
// fine enough that its own error (from the clamped cosine's kink and the sun's rim) is far
// below the truncation error it measures (docs/sh.md gives the numbers).
const std::vector<sh::Sample>& exact_quadrature() {
  static const std::vector<sh::Sample> samples = sh::gauss_legendre_samples(kExactQuadratureTheta, kExactQuadraturePhi);
  return samples;
}

// A light given by a radiance function in its own (untuned) SH frame.
class FunctionLight final : public ShLight {
 public:
  FunctionLight(std::function<glm::dvec3(const glm::dvec3&)> radiance_sh,
                std::function<std::vector<glm::dvec3>(int)> coefficients, const glm::dmat3& turn)
      : radiance_sh_(std::move(radiance_sh)), coefficients_(std::move(coefficients)), turn_(turn) {}

  std::vector<glm::dvec3> coefficients(int bands) const override {
    return sh::rotate(bands, sh::to_sh_frame(turn_), coefficients_(bands));
  }
  // The turned light at a scene-frame direction: the original light at turn^T ω.
  glm::dvec3 radiance(const glm::dvec3& scene_direction) const {
    return radiance_sh_(to_sh(glm::transpose(turn_) * scene_direction));
  }
  // The returned function outlives the light: it holds copies, never `this`.
  std::function<glm::dvec3(const glm::dvec3&)> exact_unshadowed(const glm::dvec3& albedo) const override {
    return [radiance_sh = radiance_sh_, inverse = glm::transpose(turn_), albedo](const glm::dvec3& normal) {
      const glm::dvec3 n = glm::normalize(normal);
      glm::dvec3 sum(0.0);
      for (const sh::Sample& s : exact_quadrature()) {
        const glm::dvec3 d = sh::from_sh_frame(s.direction);
        const double c = glm::dot(n, d);
        if (c > 0) sum += s.weight * c * radiance_sh(to_sh(inverse * d));
      }
      return albedo * std::numbers::inv_pi * sum;
    };
  }
  glm::dvec3 exact_at(const sh::TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                      const glm::dvec3& albedo, bool shadowed) const override {
    return sh::exact_diffuse_radiance(scene, point, normal, albedo,
                                      [this](const glm::dvec3& d) { return radiance(d); }, exact_quadrature(), shadowed);
  }

 private:
  std::function<glm::dvec3(const glm::dvec3&)> radiance_sh_;
  std::function<std::vector<glm::dvec3>(int)> coefficients_;
  glm::dmat3 turn_;
};

// D3DXSHEvalDirectionalLight's light: exactly a delta (sh/Lights.h).
class DirectionalShLight final : public ShLight {
 public:
  DirectionalShLight(sh::DirectionalLight light, const glm::dvec3& scene_direction, const glm::dmat3& turn)
      : light_(light), scene_direction_(glm::normalize(turn * scene_direction)), turn_(turn) {}

  std::vector<glm::dvec3> coefficients(int bands) const override {
    return sh::rotate(bands, sh::to_sh_frame(turn_), light_.coefficients(bands));
  }
  std::function<glm::dvec3(const glm::dvec3&)> exact_unshadowed(const glm::dvec3& albedo) const override {
    return [colour = light_.colour, direction = scene_direction_, albedo](const glm::dvec3& normal) {
      return albedo * colour * std::max(0.0, glm::dot(glm::normalize(normal), direction));
    };
  }
  glm::dvec3 exact_at(const sh::TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                      const glm::dvec3& albedo, bool shadowed) const override {
    return sh::exact_directional(scene, point, normal, albedo, scene_direction_, light_.irradiance(), shadowed);
  }

 private:
  sh::DirectionalLight light_;
  glm::dvec3 scene_direction_;
  glm::dmat3 turn_;
};

// The analytic sky (sh/Lights.h): its quadratic base is band-limited to l <= 2, so its
// irradiance is exact from 3 bands; its sun is zonal about the sun's axis, so the sun's
// irradiance depends only on the angle between the normal and that axis, tabulated once
// by a quadrature over the sun's disc. Per pixel this costs an interpolation, not the
// 18 432-sample sphere quadrature (12 s for sh_specular's four shapes at 256x256).
class SkyShLight final : public ShLight {
 public:
  SkyShLight(const sh::SkyLight& sky, const glm::dmat3& turn) : sky_(sky), turn_(turn) {
    sh::SkyLight base = sky;
    base.sun = glm::dvec3(0.0);
    base_irradiance_ = sh::irradiance_coefficients(sh::rotate(3, sh::to_sh_frame(turn), base.coefficients(3)));
    sun_axis_ = glm::normalize(turn * sh::from_sh_frame(sky.sun_direction));
    tabulate_sun();
  }

  std::vector<glm::dvec3> coefficients(int bands) const override {
    return sh::rotate(bands, sh::to_sh_frame(turn_), sky_.coefficients(bands));
  }
  std::function<glm::dvec3(const glm::dvec3&)> exact_unshadowed(const glm::dvec3& albedo) const override {
    return [base = base_irradiance_, axis = sun_axis_, table = sun_table_, sun = sky_.sun,
            albedo](const glm::dvec3& normal) {
      const glm::dvec3 n = glm::normalize(normal);
      const glm::dvec3 e_base = sh::evaluate(base, to_sh(n));
      // Linear interpolation in cos(angle to the sun): the table's spacing keeps its error
      // below 1e-7 of the sun's irradiance.
      const double x = (std::clamp(glm::dot(n, axis), -1.0, 1.0) + 1.0) * 0.5 * double(table.size() - 1);
      const size_t i = std::min(size_t(x), table.size() - 2);
      const double f = x - double(i);
      const double e_sun = table[i] * (1.0 - f) + table[i + 1] * f;
      return albedo * std::numbers::inv_pi * (e_base + sun * e_sun);
    };
  }
  glm::dvec3 exact_at(const sh::TransferScene& scene, const glm::dvec3& point, const glm::dvec3& normal,
                      const glm::dvec3& albedo, bool shadowed) const override {
    return sh::exact_diffuse_radiance(scene, point, normal, albedo,
                                      [this](const glm::dvec3& d) { return sky_(to_sh(glm::transpose(turn_) * d)); },
                                      exact_quadrature(), shadowed);
  }

 private:
  // sun_table_[k] = ∫_disc u(ω)² max(0, n·ω) dω for n at cos(angle to the axis) = -1 + 2k/K:
  // Gauss-Legendre in cos of the angle from the axis times a periodic rule in azimuth,
  // which the clamp's kink (only where the disc straddles n's horizon) limits to ~1e-6.
  // It depends on the sun's radius alone, so a process tabulates it once (~1 s) for every
  // shape, light rotation and group.
  void tabulate_sun() {
    static std::mutex mutex;
    static std::map<double, std::vector<double>> tables;   // by sun radius
    const std::lock_guard lock(mutex);
    auto [table, added] = tables.try_emplace(sky_.sun_radius);
    if (added) table->second = sun_table(sky_.sun_radius);
    sun_table_ = table->second;
  }

  static std::vector<double> sun_table(double sun_radius) {
    constexpr int entries = 4097, rings = 48, azimuths = 256;
    const double rim = std::cos(sun_radius);
    const sh::GaussLegendre rule = sh::gauss_legendre(rings);
    std::vector<double> table(entries, 0.0);
    for (int k = 0; k < entries; ++k) {
      const double c = -1.0 + 2.0 * k / (entries - 1), sn = std::sqrt(std::max(0.0, 1.0 - c * c));
      double sum = 0;
      for (int r = 0; r < rings; ++r) {
        const double mu = rim + (1.0 - rim) * 0.5 * (rule.nodes[size_t(r)] + 1.0);   // nodes on [-1, 1]
        const double w_mu = (1.0 - rim) * 0.5 * rule.weights[size_t(r)];
        const double u = (mu - rim) / (1.0 - rim), sin_mu = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        double ring = 0;
        for (int a = 0; a < azimuths; ++a) {
          const double phi = 2.0 * std::numbers::pi * (a + 0.5) / azimuths;
          ring += std::max(0.0, sn * sin_mu * std::cos(phi) + c * mu);
        }
        sum += w_mu * u * u * ring * (2.0 * std::numbers::pi / azimuths);
      }
      table[size_t(k)] = sum;
    }
    return table;
  }

  sh::SkyLight sky_;
  glm::dmat3 turn_;
  std::vector<glm::dvec3> base_irradiance_;
  glm::dvec3 sun_axis_;
  std::vector<double> sun_table_;
};

}  // namespace

Result<std::unique_ptr<ShLight>> make_sh_light(const ShSetup& setup, const Case& c, const SceneSetup& scene,
                                               const glm::dmat3& turn) {
  auto fail_light = [&](std::string message) {
    return std::unexpected(Error{.message = std::move(message), .file = c.path, .line = setup.line, .stage = ErrorStage::sh});
  };
  const glm::dvec3 white(1.0);
  if (setup.light == "directional") {
    auto light = sh::make_directional_light(to_sh(scene.lights.direction), white);
    if (!light) return fail_light(light.error());
    return std::make_unique<DirectionalShLight>(*light, scene.lights.direction, turn);
  }
  if (setup.light == "cone") {
    auto light = sh::make_cone_light(to_sh(scene.lights.direction), c.params.at("cone_radius").at(0), white);
    if (!light) return fail_light(light.error());
    const sh::ConeLight cone = *light;
    return std::make_unique<FunctionLight>([cone](const glm::dvec3& d) { return cone(d); },
                                           [cone](int bands) { return cone.coefficients(bands); }, turn);
  }
  if (setup.light == "sky") return std::make_unique<SkyShLight>(sh::SkyLight{}, turn);
  auto map = read_probe(setup.probe, setup.mapping == "angular" ? sh::MapLayout::angular : sh::MapLayout::latlong);
  if (!map) return std::unexpected(Error(map.error()).in_file(c.path));
  auto shared = std::make_shared<const sh::EnvironmentMap>(std::move(*map));
  return std::make_unique<FunctionLight>(
      [shared](const glm::dvec3& d) { return shared->lookup(d); },
      [shared](int bands) { return sh::project_rgb([&](const glm::dvec3& d) { return shared->lookup(d); },
                                                   sh::SampleSet(exact_quadrature(), bands)); },
      turn);
}

}  // namespace shaderbed
