#pragma once
// Lighting models by name. model_names(), default_params() and evaluate() (declared in
// Reference.h) are built on this table.
#include <string_view>

#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

// Which of the scene's lights a model reads, so evaluate() knows where to put them.
enum class LightUse {
  none,         // ambient
  directional,  // light_vector (lambert ... cook_torrance)
  point,        // light_position (point_attenuated)
  spot,         // light_position, with light_vector as the spot's (negated) axis (spot, warn)
};

struct ModelInfo {
  std::string_view name;
  ModelOrError (*make)(const Params&);
  Params (*defaults)();
  LightUse light;
};

// The registered model of that name, or null.
const ModelInfo* find_model(std::string_view name);

// Builds the named model from its parameters; an unknown name or a missing or
// malformed parameter comes back as an error naming the model and the parameter.
ModelOrError make_model(std::string_view name, const Params& params);

}  // namespace reference
