#pragma once
// The scene's part of the lighting, around any model: which light a directional-light
// model sees (Scene::light) and the ambient colour added to its output (Scene::ambient).
#include <string_view>

#include <glm/glm.hpp>

#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

// `model` (built for `model_name`) following the scene's light and ambient term; the
// same model when both are the defaults. An error when the light does not apply to the
// model (a point-light model asked to use the directional light).
ModelOrError with_scene_lighting(std::unique_ptr<const LightingModel> model, std::string_view model_name,
                                 SceneLight light, const glm::dvec3& ambient);

}  // namespace reference
