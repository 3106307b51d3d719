#pragma once
// How render() shades a pixel, shared with model_quantities() (ModelQuantities.h) so that
// the quantities are reported at exactly the point, with exactly the model and lighting,
// that render() shades: the model a scene and a model name give (the scene's light and
// ambient around it), the lighting each shaded point sees under a perturbation, and the
// surface point and lighting of a covered pixel.
#include <array>
#include <expected>
#include <memory>
#include <string>

#include "reference/LightingModel.h"
#include "reference/ModelRegistry.h"
#include "reference/Rasteriser.h"
#include "reference/Reference.h"
#include "reference/StableVector.h"

namespace reference {

// The named model built from `params`, following the scene's light and ambient term, and
// which light it reads; errors as render()'s.
struct SceneModel {
  std::unique_ptr<const LightingModel> model;
  LightUse light = LightUse::none;
};
std::expected<SceneModel, std::string> scene_model(const Scene& scene, const std::string& model_name,
                                                   const Params& params);

// The lighting one shaded point sees: the scene's, or the scene's under a perturbation.
// Built once per shaded point, outside the models, so no model needs to know about perturbations.
class PointLighting {
 public:
  PointLighting(const ObjectSpaceLighting& lighting, const Perturbation& perturbation, LightUse light_use,
                SceneLight scene_light)
      : lighting_(lighting),
        perturbation_(perturbation),
        // Only the directional-light models take light_direction as L; the spot and Warn
        // lights take it as their axis, which L -> -L leaves alone.
        negate_direction_(perturbation.negate_light && light_use == LightUse::directional),
        point_lit_(light_use == LightUse::point || light_use == LightUse::spot ||
                   (light_use == LightUse::directional && scene_light == SceneLight::point)),
        directional_(light_use == LightUse::directional) {}

  ObjectSpaceLighting at(const glm::dvec3& position) const {
    ObjectSpaceLighting at_point = lighting_;
    if (negate_direction_) at_point.light_direction = -lighting_.light_direction;
    // Reflecting the point light through P flips Lp and keeps its distance; a model lit
    // by the directional light never reads the position, so this is harmless for it.
    if (perturbation_.negate_light) at_point.light_position = 2.0 * position - lighting_.light_position;
    if (perturbation_.negate_eye) at_point.eye_position = 2.0 * position - lighting_.eye_position;
    return at_point;
  }

  // at(position), with L and V taken from the triangle's corners as a vertex stage would
  // have passed them (Perturbation::interpolated_light_eye).
  ObjectSpaceLighting at(const glm::dvec3& position, const std::array<glm::dvec3, 3>& corners,
                         const glm::dvec3& weights) const {
    ObjectSpaceLighting at_point = at(position);
    if (!perturbation_.interpolated_light_eye) return at_point;
    glm::dvec3 to_light(0.0), to_eye(0.0);
    for (int i = 0; i < 3; ++i) {
      const ObjectSpaceLighting at_corner = at(corners[i]);
      to_light += weights[i] * (point_lit_ ? stable::normalize(at_corner.light_position - corners[i])
                                           : at_corner.light_direction);
      to_eye += weights[i] * stable::normalize(at_corner.eye_position - corners[i]);
    }
    at_point.to_eye = to_eye;
    if (point_lit_) at_point.to_light = to_light;
    else if (directional_) at_point.light_direction = to_light;
    return at_point;
  }

 private:
  ObjectSpaceLighting lighting_;
  Perturbation perturbation_;
  bool negate_direction_;
  bool point_lit_;     // L = normalize(light_position - P)
  bool directional_;   // L = light_direction
};

// What render() shades a covered pixel with, per pixel: the vertex attributes interpolated
// as given (like the varyings a vertex shader passes through), the normal normalised (unless
// the perturbation says not to, or replaces it with the facet's), and the lighting there.
struct PixelInput {
  SurfacePoint point;
  ObjectSpaceLighting lighting;
};
PixelInput pixel_input(const Mesh& mesh, const VisibleSample& sample, const PointLighting& lighting,
                       const Perturbation& perturbation);

}  // namespace reference
