#pragma once
// The CPU reference renderer: rasterises a triangle mesh with the GPUs' rules (pixel
// centres at .5, 8-bit sub-pixel snapping, top-left fill rule, perspective-correct
// interpolation, depth test LESS) and evaluates a named lighting model in double
// precision, per vertex (shade at vertices, interpolate the colour) or per pixel
// (interpolate position and normal, normalise, shade).
//
// It knows lighting *models*, never shader code, and depends on nothing in harness/.
#include <cstdint>
#include <expected>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace reference {

struct Vertex {
  glm::dvec3 position;
  glm::dvec3 normal;
  glm::dvec3 tangent;
  glm::dvec2 uv;
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;   // triangle list
};

// The camera in world space. The projection is left-handed with depth in [0, 1]
// (D3D conventions, as the book's D3DXMatrixLookAtLH); NDC y = +1 is image row 0.
struct Camera {
  glm::dvec3 eye{-100, 50, 0};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double fovy_degrees = 45;
  double near_plane = 1;
  double far_plane = 1000;
};

// World-space lights; the reference moves them into object space itself.
struct Lights {
  glm::dvec3 direction{0, 1, 0};     // unit vector toward a directional light
  glm::dvec3 position{0, 50, 0};     // point light position (w = 1)
};

struct Scene {
  Mesh mesh;
  glm::dmat4 world{1.0};             // object -> world
  Camera camera;
  Lights lights;
  int width = 256;
  int height = 256;
};

enum class Mode { per_vertex, per_pixel };

// Model parameters by name; scalars have one value, colours three (or four).
using Params = std::map<std::string, std::vector<double>>;

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<double> rgba;          // width * height * 4, row 0 = top
  std::vector<uint8_t> coverage;     // 1 where a triangle covered the pixel centre
};

// The model names the harness may ask for ("ambient", "lambert", "phong", ...).
std::vector<std::string> model_names();

// Renders the scene with the named model. Errors (unknown model, missing parameter)
// come back as text.
std::expected<Framebuffer, std::string> render(const Scene& scene, const std::string& model, Mode mode,
                                               const Params& params);

// Matrices the reference uses, exposed so the harness can check its own against them.
glm::dmat4 view_matrix(const Camera&);
glm::dmat4 projection_matrix(const Camera&, double aspect);

}  // namespace reference
