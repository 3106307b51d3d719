#pragma once
// What the reference's rasteriser sees at each pixel, before any lighting model: the
// geometry a convention fit needs (the harness explains a failing render with it, e.g.
// "the render has an extra N·L factor", "the render's normal is not renormalised").
// Same rasteriser, same coverage as render(): a pixel is covered here exactly when it is
// covered in render()'s framebuffer.
#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "reference/Reference.h"

namespace reference {

// One covered pixel, in object space (where the models shade).
struct SurfaceSample {
  glm::dvec3 position{0.0};
  glm::dvec3 normal{0.0};    // interpolated, NOT normalised: its length is below 1 inside a
                             // triangle of a tessellated sphere (the chord of unit normals)
  glm::dvec3 to_light{0.0};  // unit L toward the light (see render_surface)
  glm::dvec3 to_eye{0.0};    // unit V = normalize(eye - P)
  glm::dvec2 uv{0.0};
};

struct SurfaceBuffer {
  int width = 0;
  int height = 0;
  std::vector<SurfaceSample> samples;  // width * height, row 0 = top; zeros where uncovered
  std::vector<uint8_t> coverage;       // 1 where a triangle covered the pixel centre
};

// The scene's visible surface. L follows Scene::light: `point` gives
// normalize(light_position - P); `directional` and `model_default` give the object-space
// directional light. The surface knows no model, so model_default counts as directional
// here: for a point-light model (point_attenuated, spot, warn) pass SceneLight::point to
// get the L it shades with. Errors as render()'s for an empty image or a malformed mesh.
std::expected<SurfaceBuffer, std::string> render_surface(const Scene& scene);

}  // namespace reference
