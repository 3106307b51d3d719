#include "prt/ShLight.h"

#include "prt/ProbeFile.h"

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
  static const std::vector<sh::Sample> samples = sh::gauss_legendre_samples(96, 192);
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

}  // namespace

Result<std::unique_ptr<ShLight>> make_sh_light(const ShSetup& setup, const Case& c, const SceneSetup& scene,
                                               const glm::dmat3& turn) {
  auto fail_light = [&](std::string message) {
    return std::unexpected(Error{.message = std::move(message), .file = c.path, .line = setup.line, .stage = "sh"});
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
  if (setup.light == "sky") {
    const sh::SkyLight sky;
    return std::make_unique<FunctionLight>([sky](const glm::dvec3& d) { return sky(d); },
                                           [sky](int bands) { return sky.coefficients(bands); }, turn);
  }
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
