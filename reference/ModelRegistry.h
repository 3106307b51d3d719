#pragma once
// Lighting models by name. model_names() (declared in Reference.h) lists them.
#include <string_view>

#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

// Builds the named model from its parameters; an unknown name or a missing or
// malformed parameter comes back as an error naming the model and the parameter.
ModelOrError make_model(std::string_view name, const Params& params);

}  // namespace reference
