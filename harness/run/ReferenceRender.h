#pragma once
// Adapter from the harness's scene to the independent CPU reference.
#include "compare/ImageComparison.h"
#include "scene/CaseFile.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

namespace shaderbed {

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode);

}  // namespace shaderbed
