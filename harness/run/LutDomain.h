#pragma once
// What a LUT variant's error bound is taken over: the shading configurations one shape
// shows in the drawn image (harness/lut/LutTolerance.h), from the reference's own
// rasterisation of the scene, so the bound follows the shape, the light and the image
// size rather than the whole table.
#include "core/Error.h"
#include "lut/LutTolerance.h"
#include "scene/CaseFile.h"
#include "pipeline/Mesh.h"
#include "scene/Scene.h"

namespace shaderbed {

// The interior pixels' configurations exactly (the pixels that are judged against the
// interior tolerance), and for the silhouette band the covered pixels of each band
// pixel's 3x3 neighbourhood plus their attributes extrapolated one pixel outward.
Result<LutDomain> lut_domain(const Case& c, const Mesh& mesh, const SceneSetup& scene, const std::string& shape);

}  // namespace shaderbed
