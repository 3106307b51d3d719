#pragma once
// Adapter from the harness's scene to the independent CPU reference.
#include "compare/ImageComparison.h"
#include "compare/SurfaceSamples.h"
#include "reference/LightingModel.h"
#include "scene/CaseFile.h"
#include "pipeline/Mesh.h"
#include "scene/Scene.h"

namespace reference {
struct Perturbation;
struct Scene;
}

namespace shaderbed {

Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode);

// The same with a lighting the caller computed (an SH case's, harness/prt).
Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode,
                                        const reference::LightingModel& model);

// The same model re-rendered under a convention (light or eye negated, the normal not
// renormalised): what a port that got that convention wrong would draw.
Result<ReferenceImage> render_reference(const Mesh& mesh, const SceneSetup& scene, const Case& c, LightingMode mode,
                                        const reference::Perturbation& perturbation);

// The reference's scene for the case: the mesh, camera, world matrix, lights and ambient
// the cells are drawn with.
reference::Scene reference_scene(const Mesh& mesh, const SceneSetup& scene, const Case& c);

// The reference's scene for the case's visible surface: its light is the one the model
// shades with (the point light for the point- and spot-light models, else the case's).
reference::Scene surface_scene(const Mesh& mesh, const SceneSetup& scene, const Case& c);

// N·L, N·V and the interpolated normal's length per pixel, for the convention fits.
Result<SurfaceSamples> render_surface_samples(const Mesh& mesh, const SceneSetup& scene, const Case& c);

}  // namespace shaderbed
