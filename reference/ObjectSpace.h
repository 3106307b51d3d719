#pragma once
// Moves the world-space lights and eye into the object space the models work in.
#include <glm/glm.hpp>

#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference {

// Directions go through the inverse world matrix with w = 0 and are renormalised;
// positions (light, eye) with w = 1. (The book transforms positions with w = 0, an
// erratum: that drops the world translation.)
ObjectSpaceLighting to_object_space(const Lights& lights, const Camera& camera, const glm::dmat4& world);

}  // namespace reference
