#pragma once
// One factory per model, each defined in its own file in this folder. A new model is a
// new file here, a declaration below and a line in ModelRegistry.cpp.
#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

ModelOrError make_ambient(const Params& params);  // ambient
ModelOrError make_lambert(const Params& params);  // diffuse
ModelOrError make_phong(const Params& params);    // diffuse, specular, power

}  // namespace reference
