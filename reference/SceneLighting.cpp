#include "reference/SceneLighting.h"

#include <optional>
#include <string>
#include <string_view>
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
    return model_->shade(point, lit(point, lighting));
  }

  // The model's quantities, its "L" being the point light's; before them the vector to the
  // light and its length, which a point-light shader computes first.
  void quantities(const SurfacePoint& point, const ObjectSpaceLighting& lighting, QuantitySink& sink) const override {
    const glm::dvec3 to_light = lighting.light_position - point.position;
    sink.vector("light_position−P", to_light, VectorKind::displacement);
    sink.scalar("d", stable::length(to_light));
    model_->quantities(point, lit(point, lighting), sink);
  }

 private:
  static ObjectSpaceLighting lit(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
    ObjectSpaceLighting at_point = lighting;
    at_point.light_direction = lighting.to_light.value_or(stable::normalize(lighting.light_position - point.position));
    return at_point;
  }

  std::unique_ptr<const LightingModel> model_;
};

// Passes a model's quantities on, its "colour" as "model colour", and keeps that colour.
class ModelColour final : public QuantitySink {
 public:
  explicit ModelColour(QuantitySink& sink) : sink_(sink) {}

  void scalar(std::string_view name, double value) override { sink_.scalar(name, value); }
  void vector(std::string_view name, const glm::dvec3& value, VectorKind kind) override {
    if (name != "colour") return sink_.vector(name, value, kind);
    colour = value;
    sink_.vector("model colour", value, kind);
  }

  std::optional<glm::dvec3> colour;

 private:
  QuantitySink& sink_;
};

// The model's colour plus the ambient light's.
class WithAmbient final : public LightingModel {
 public:
  WithAmbient(std::unique_ptr<const LightingModel> model, const glm::dvec3& ambient)
      : model_(std::move(model)), ambient_(ambient) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    return model_->shade(point, lighting) + ambient_;
  }

  // The model's quantities, its colour as "model colour" (the same value as its shade()),
  // then the scene's "ambient_light" and the sum, "colour": shade()'s sum of the same values.
  void quantities(const SurfacePoint& point, const ObjectSpaceLighting& lighting, QuantitySink& sink) const override {
    ModelColour model_sink(sink);
    model_->quantities(point, lighting, model_sink);
    const glm::dvec3 model_colour = model_sink.colour ? *model_sink.colour : model_->shade(point, lighting);
    sink.vector("ambient_light", ambient_, VectorKind::colour);
    sink.vector("colour", model_colour + ambient_, VectorKind::colour);
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
