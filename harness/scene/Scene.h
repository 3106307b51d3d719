#pragma once
// The book's scene (lights-and-brdfs.md §5.3): object at the origin, eye at
// (-100, 50, 0) looking at it with +Y up (left-handed, as D3DXMatrixLookAtLH), a
// directional light from +Y and a point light at (0, 50, 0). Lights and eye are moved
// into object space with the inverse world matrix: positions with w = 1, directions
// with w = 0 (the book's w = 0 for positions is an erratum).
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shaderbed {

struct Camera {
  glm::dvec3 eye{-100, 50, 0};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double fovy_degrees = 45;
  double near_plane = 1;
  double far_plane = 1000;
};

struct Lights {
  glm::dvec3 direction{0, 1, 0};   // toward the directional light
  glm::dvec3 position{0, 50, 0};   // point light
  glm::dvec3 ambient{0, 0, 0};     // ambient light colour (a case's `ambient`), "ambient_light"
};

struct SceneSetup {
  Camera camera;
  Lights lights;
  glm::dmat4 world{1.0};
  // Added to clip x, y (times w) in the bindable projections: (1/width, -1/height) is
  // D3D9's half-pixel offset. Zero except when the runner re-draws a counterfactual.
  glm::dvec2 clip_offset{0.0};
  int width = 256;
  int height = 256;
};

// The quantities a shader can bind by name (docs/models.md, "Scene quantities"), every
// matrix as 16 column-major floats of M in "clip = M v" (3x3 ones as 9):
//  - matrices: "world", "view", "projection" (depth in [0, 1]), "world_view",
//    "view_projection", "transform" (= projection * view * world); each also with the
//    suffixes "_inverse", "_transpose" and "_inverse_transpose";
//  - "normal_matrix" (3x3 inverse-transpose of world), "normal_matrix_view" (of world_view);
//  - "light_vector" (unit, toward the directional light, w = 0), "light_position" and
//    "eye_position" (w = 1) in object space, and the same with "_world" and "_view";
//  - "ambient_light" (r, g, b, 1): the scene's ambient colour.
using NamedValues = std::map<std::string, std::vector<double>>;   // in double until a backend packs them
NamedValues scene_quantities(const SceneSetup& scene);

glm::dmat4 view_matrix(const Camera&);
glm::dmat4 projection_matrix(const Camera&, double aspect);

}  // namespace shaderbed
