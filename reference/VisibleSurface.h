#pragma once
// The part of rendering that does not depend on the lighting model: check the scene,
// transform the mesh to clip space, rasterise, and interpolate the attributes a covered
// pixel sees. render() shades on top of it; render_surface() (Surface.h) reports it, so
// both see exactly the same pixels.
#include <array>
#include <expected>
#include <string>

#include "reference/LightingModel.h"
#include "reference/Rasteriser.h"
#include "reference/Reference.h"

namespace reference {

// The scene's mesh rasterised with the GPUs' rules (Rasteriser.h), or an error for an
// empty image or a malformed mesh.
std::expected<VisibilityBuffer, std::string> rasterise_scene(const Scene& scene);

// The three vertex indices of the triangle a covered sample sees.
std::array<uint32_t, 3> triangle_corners(const Mesh& mesh, const VisibleSample& sample);

// The vertex attributes interpolated at a covered sample, as a vertex shader's varyings
// arrive: the normal is NOT normalised here (its length tells how far it is from unit).
SurfacePoint interpolate_surface(const Mesh& mesh, const VisibleSample& sample);

}  // namespace reference
