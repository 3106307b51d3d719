#pragma once
// The area, in pixels, a mesh covers on screen, computed from the mesh alone so it can
// check both the GPU renders and the CPU reference (neither rasteriser's fill rule,
// snapping or pixel-centre sampling is involved).
//
// Method: every triangle is clipped in homogeneous clip space to the view volume
// (-w <= x, y <= w, 0 <= z <= w: the "transform" convention, depth in [0, 1]) and
// projected with the viewport x = (x/w + 1) W / 2, y = (1 - y/w) H / 2. The union of the
// projected triangles is then integrated exactly in x and by the midpoint rule in y: the
// image is cut into horizontal slabs at every projected vertex height and at
// `scanlines_per_pixel` even cuts per pixel row; in the middle of each slab the exact
// x-interval of every triangle crossing it is computed in double precision, the
// intervals are merged (so overlaps, e.g. the torus's front and back, count once) and
// the merged length times the slab height is added.
//
// Accuracy: inside a slab no triangle starts or ends, so the covered width is linear in
// y except where two edges of the union's boundary cross (a kink); the midpoint rule is
// exact for linear widths. The union of a convex mesh's triangles has its kinks at
// projected vertices only, so its area is exact up to rounding (~1e-9 px). Where edges
// of a non-convex mesh cross on the boundary (the torus's hole) each crossing adds at
// most h^2 |slope change| / 8 with h = 1/scanlines_per_pixel: with the default 16 that
// is far below one pixel for the whole image (the tests check exact polygon areas to
// 1e-6 px and the analytic sphere silhouette to its tessellation error).
#include <glm/glm.hpp>

#include "pipeline/Mesh.h"

namespace shaderbed {

// The area in pixels of the union of the mesh's triangles (all of them: no face culling)
// inside the width x height viewport. Triangles with a non-finite vertex are skipped.
double projected_area_pixels(const Mesh& mesh, const glm::dmat4& clip_from_object, int width, int height,
                             int scanlines_per_pixel = 16);

}  // namespace shaderbed
