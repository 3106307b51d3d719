#pragma once
// Adapter from the harness's scene to the independent CPU reference.
#include "compare/ImageComparison.h"
#include "compare/SurfaceSamples.h"
#include "scene/CaseFile.h"
#include "scene/Mesh.h"
#include "scene/Scene.h"

namespace reference {
struct Perturbation;
}

namespace shaderbed {

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode);

// The same model re-rendered under a convention (light or eye negated, the normal not
// renormalised): what a port that got that convention wrong would draw.
Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode,
                                        const reference::Perturbation& perturbation);

// N·L, N·V and the interpolated normal's length per pixel, for the convention fits. L is
// the case's light (a point light when the case or its model uses one).
Result<SurfaceSamples> render_surface_samples(const Mesh& mesh, const SceneSetup& scene, const Case& c);

}  // namespace shaderbed
