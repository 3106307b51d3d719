// evaluate(): one model at one configuration, for `shaderbed eval` and the unit tests.
#include <algorithm>
#include <cmath>

#include "reference/ModelRegistry.h"
#include "reference/Reference.h"
#include "reference/StableVector.h"

namespace reference {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Any finite non-zero vector has a direction: normalised with a scaled norm, so lengths
// whose squares under- or overflow (1e-200, 1e200) are accepted.
std::expected<glm::dvec3, std::string> unit(const glm::dvec3& v, const char* what) {
  if (!finite(v) || v == glm::dvec3(0.0)) {
    return std::unexpected(std::string(what) + " must be a finite, non-zero vector");
  }
  return stable::normalize(v);
}

bool is_lut_parameter(const std::string& name) { return name == "lut_size" || name == "lut_rows"; }

}  // namespace

std::expected<glm::dvec3, std::string> evaluate(const std::string& model_name, const Params& params,
                                                const Configuration& configuration) {
  const ModelInfo* info = find_model(model_name);
  if (!info) return std::unexpected(make_model(model_name, {}).error());  // the unknown-model message

  Params merged = info->defaults();
  for (const auto& [name, values] : params) {
    if (is_lut_parameter(name)) continue;
    if (!merged.contains(name)) {
      std::string known;
      for (const auto& [parameter, defaults] : merged) known += (known.empty() ? "" : ", ") + parameter;
      return std::unexpected(model_name + ": unknown parameter '" + name + "' (parameters: " + known + ")");
    }
    merged[name] = values;
  }
  auto model = info->make(merged);
  if (!model) return std::unexpected(model.error());

  const auto to_light = unit(configuration.to_light, "L (to the light)");
  if (!to_light) return std::unexpected(to_light.error());
  const auto to_eye = unit(configuration.to_eye, "V (to the eye)");
  if (!to_eye) return std::unexpected(to_eye.error());
  const auto normal = unit(configuration.normal, "N (the normal)");
  if (!normal) return std::unexpected(normal.error());
  if (!finite(configuration.tangent)) return std::unexpected("T (the tangent) must be finite");
  if (!(configuration.distance > 0) || !std::isfinite(configuration.distance)) {
    return std::unexpected("the light distance must be finite and > 0");
  }
  const auto axis = unit(configuration.spot_axis.value_or(-*normal), "the spot axis");
  if (!axis) return std::unexpected(axis.error());

  ObjectSpaceLighting lighting{*to_light, configuration.distance * *to_light, *to_eye};
  if (info->light == LightUse::spot) lighting.light_direction = -*axis;  // light_vector = -axis
  const SurfacePoint point{glm::dvec3(0.0), *normal, configuration.tangent, glm::dvec2(0.0)};
  return (*model)->shade(point, lighting);
}

std::expected<glm::dvec3, std::string> evaluate(const std::string& model, const Params& params, const glm::dvec3& L,
                                                const glm::dvec3& V, const glm::dvec3& N, const glm::dvec3& T,
                                                double distance) {
  return evaluate(model, params, Configuration{L, V, N, T, distance, std::nullopt});
}

}  // namespace reference
