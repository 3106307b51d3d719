#pragma once
#include "scene/CaseFile.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

namespace shaderbed {

// The largest factor a Warn-style light puts in front of its LUT term on this shape:
// max(diffuse) * max(light_color) / d^2 at the surface point nearest the light (1 when
// the model has no light colour). Feeds lut_error_bound().
double lut_light_scale(const Case& c, const Mesh& mesh, const SceneSetup& scene);

}  // namespace shaderbed
