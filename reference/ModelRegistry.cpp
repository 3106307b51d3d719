#include "reference/ModelRegistry.h"

#include <array>

#include "reference/models/Models.h"

namespace reference {
namespace {

// An explicit table rather than self-registering statics: this is a static library, and
// the linker drops object files nothing refers to, registrations included.
constexpr std::array registered_models{
    ModelInfo{"ambient", make_ambient, ambient_defaults, LightUse::none},
    ModelInfo{"lambert", make_lambert, lambert_defaults, LightUse::directional},
    ModelInfo{"phong", make_phong, phong_defaults, LightUse::directional},
    ModelInfo{"blinn_phong", make_blinn_phong, blinn_phong_defaults, LightUse::directional},
    ModelInfo{"schlick", make_schlick, schlick_defaults, LightUse::directional},
    ModelInfo{"minnaert", make_minnaert, minnaert_defaults, LightUse::directional},
    ModelInfo{"oren_nayar", make_oren_nayar, oren_nayar_defaults, LightUse::directional},
    ModelInfo{"ward_iso", make_ward_iso, ward_iso_defaults, LightUse::directional},
    ModelInfo{"ward_aniso", make_ward_aniso, ward_aniso_defaults, LightUse::directional},
    ModelInfo{"cook_torrance", make_cook_torrance, cook_torrance_defaults, LightUse::directional},
    ModelInfo{"point_attenuated", make_point_attenuated, point_attenuated_defaults, LightUse::point},
    ModelInfo{"spot", make_spot, spot_defaults, LightUse::spot},
    ModelInfo{"warn", make_warn, warn_defaults, LightUse::spot},
};

std::string unknown_model(std::string_view name) {
  std::string known;
  for (const ModelInfo& model : registered_models) known += (known.empty() ? "" : ", ") + std::string(model.name);
  return "unknown lighting model '" + std::string(name) + "' (known: " + known + ")";
}

}  // namespace

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const ModelInfo& model : registered_models) names.emplace_back(model.name);
  return names;
}

const ModelInfo* find_model(std::string_view name) {
  for (const ModelInfo& model : registered_models) {
    if (model.name == name) return &model;
  }
  return nullptr;
}

ModelOrError make_model(std::string_view name, const Params& params) {
  if (const ModelInfo* model = find_model(name)) return model->make(params);
  return std::unexpected(unknown_model(name));
}

std::expected<Params, std::string> default_params(const std::string& name) {
  if (const ModelInfo* model = find_model(name)) return model->defaults();
  return std::unexpected(unknown_model(name));
}

std::vector<std::string> model_parameters(const std::string& name) {
  std::vector<std::string> names;
  if (const ModelInfo* model = find_model(name)) {
    for (const auto& [parameter, values] : model->defaults()) names.push_back(parameter);
  }
  return names;
}

}  // namespace reference
