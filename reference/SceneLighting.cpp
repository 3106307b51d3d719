#include "reference/SceneLighting.h"

#include <string>
#include <utility>

#include "reference/ModelRegistry.h"
#include "reference/StableVector.h"

namespace reference {
namespace {

// A directional-light model lit by the point light: its light_direction becomes
// normalize(light_position - P) at every point it shades (or L as a perturbation gives it).
class PointLit final : public LightingModel {
 public:
  explicit PointLit(std::unique_ptr<const LightingModel> model) : model_(std::move(model)) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    ObjectSpaceLighting at_point = lighting;
    at_point.light_direction = lighting.to_light.value_or(stable::normalize(lighting.light_position - point.position));
    return model_->shade(point, at_point);
  }

 private:
  std::unique_ptr<const LightingModel> model_;
};

// The model's colour plus the ambient light's.
class WithAmbient final : public LightingModel {
 public:
  WithAmbient(std::unique_ptr<const LightingModel> model, const glm::dvec3& ambient)
      : model_(std::move(model)), ambient_(ambient) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    return model_->shade(point, lighting) + ambient_;
  }

 private:
  std::unique_ptr<const LightingModel> model_;
  glm::dvec3 ambient_;
};

}  // namespace

ModelOrError with_scene_lighting(std::unique_ptr<const LightingModel> model, std::string_view model_name,
                                 SceneLight light, const glm::dvec3& ambient) {
  const ModelInfo* info = find_model(model_name);
  const LightUse use = info ? info->light : LightUse::none;
  if (light == SceneLight::directional && (use == LightUse::point || use == LightUse::spot))
    return std::unexpected("model '" + std::string(model_name) +
                           "' is lit by the point light; light = \"directional\" does not apply to it");
  if (light == SceneLight::point && use == LightUse::directional) model = std::make_unique<PointLit>(std::move(model));
  if (ambient != glm::dvec3(0.0)) model = std::make_unique<WithAmbient>(std::move(model), ambient);
  return model;
}

}  // namespace reference
