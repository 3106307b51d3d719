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
#include <optional>
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

// Which light the directional-light models (lambert ... cook_torrance) use: their own
// directional light by default; `point` gives them L = normalize(light_position - P)
// instead (the book's Ch. 2 lights are point lights). The point-light models
// (point_attenuated, spot, warn) always use the point light: `directional` is an error.
enum class SceneLight { model_default, directional, point };

struct Scene {
  Mesh mesh;
  glm::dmat4 world{1.0};             // object -> world
  Camera camera;
  Lights lights;
  SceneLight light = SceneLight::model_default;
  glm::dvec3 ambient{0.0};           // ambient light colour, added to every model's output
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

// A convention the model is rendered under instead of the correct one, so the harness can
// ask "does the render match the reference if the shader had done X?" (counterfactual
// references). Applied where the lighting of each shaded point is built (per pixel, or
// per vertex in per-vertex mode), never inside a model, so every model gets it alike:
//  - negate_light: L -> -L. For a model lit by the directional light, its direction is
//    negated; for one lit by the point light (point_attenuated, spot, warn, or any model
//    with SceneLight::point) the light moves to 2P - Lp at each shaded point P, so its
//    distance is kept and only its direction flips. The spot and Warn lights' axis (the
//    directional light's vector) is left as it is: it is not their L.
//  - negate_eye: the eye moves to 2P - eye at each shaded point (V -> -V).
//  - unnormalised_normal: per pixel, shade with the interpolated normal as it arrives,
//    not renormalised (a shader that forgot normalize()); per vertex, no change (the
//    vertex normals are shaded as they are in the normal render).
//  - interpolated_light_eye: per pixel, L and V are built at the three vertices (unit
//    there), interpolated perspective-correctly to the pixel and shaded as they arrive,
//    not renormalised (a shader that normalises them in its vertex stage); H, R and the
//    rest are built from them per pixel as usual. A directional light's L is the same at
//    every vertex, so only V (and a point light's L) change. Per vertex, no change.
//  - faceted_normal: per pixel, shade with the triangle's geometric normal, turned to the
//    side the vertex normals face, instead of the interpolated one (a normal rebuilt
//    from screen-space derivatives, normalize(cross(ddx(P), ddy(P)))). Per vertex, no change.
struct Perturbation {
  bool negate_light = false;
  bool negate_eye = false;
  bool unnormalised_normal = false;
  bool interpolated_light_eye = false;
  bool faceted_normal = false;
};

// render() under a perturbation; Perturbation{} gives exactly render()'s image.
std::expected<Framebuffer, std::string> render(const Scene& scene, const std::string& model, Mode mode,
                                               const Params& params, const Perturbation& perturbation);

class LightingModel;

// render() with a model the caller built (a lighting computed outside the registry, e.g.
// an SH case's per-vertex radiance): no scene light or ambient term is added.
std::expected<Framebuffer, std::string> render(const Scene& scene, const LightingModel& model, Mode mode);

// ---- One configuration at a time (`shaderbed eval`) -------------------------------------

// docs/models.md's defaults (the book's values) for every parameter the named model
// reads, or an error naming the known models. The LUT variants' lut_size / lut_rows are
// not included: they are not parameters of the model, and the reference evaluates the
// analytic model for every variant.
std::expected<Params, std::string> default_params(const std::string& model);

// The names of those parameters, sorted; empty for an unknown model.
std::vector<std::string> model_parameters(const std::string& model);

// A single shading configuration in a local frame with the surface point at the origin;
// any frame works (the models depend on no fixed axis), the defaults put N along +Y as in
// the case scene. Directions need not be unit length: evaluate() normalises L, V, N (and the spot axis);
// T is used as given (ward_aniso orthogonalises it against N and normalises it).
//
// Where the lights go:
//  - directional-light models (lambert ... cook_torrance): light_vector = L;
//  - point_attenuated: the point light at distance * L, so Lp = L and d = distance;
//  - spot, warn: the light at distance * L as for point_attenuated, shining along
//    `spot_axis`, by default -N: straight down onto the surface, as the scene's light at
//    (0, 50, 0) shines down onto the top of the object. Then cos(theta) = Lp·(-axis) =
//    N·L: the point is on the axis exactly when L = N, and tilting L sweeps it through
//    the umbra, penumbra (spot) or cos^alpha cone (warn). Pass spot_axis = -L to put
//    the point on the axis for every L.
//  - the eye at V (its distance does not matter: every model uses only the direction).
struct Configuration {
  glm::dvec3 to_light{0, 1, 0};          // L
  glm::dvec3 to_eye{0, 1, 0};            // V
  glm::dvec3 normal{0, 1, 0};            // N (+Y, as the scene's light from above)
  glm::dvec3 tangent{1, 0, 0};           // T
  double distance = 50;                  // to the point light (point_attenuated, spot, warn)
  std::optional<glm::dvec3> spot_axis;   // direction the spot/Warn light shines; default -N
};

// The model's colour (outgoing radiance for a white light of unit intensity; unclamped)
// at one configuration. `params` override default_params(model): pass only what
// differs. A parameter the model does not read is an error (a typo would otherwise
// silently evaluate the default), except lut_size and lut_rows, which case files carry
// for their LUT variants and which are ignored. Other errors: unknown model, a
// malformed or out-of-domain value, a zero or non-finite direction, a distance <= 0.
std::expected<glm::dvec3, std::string> evaluate(const std::string& model, const Params& params,
                                                const Configuration& configuration);

// The same with the directions given directly.
std::expected<glm::dvec3, std::string> evaluate(const std::string& model, const Params& params,
                                                const glm::dvec3& L, const glm::dvec3& V,
                                                const glm::dvec3& N = {0, 1, 0}, const glm::dvec3& T = {1, 0, 0},
                                                double distance = 50);

// Matrices the reference uses, exposed so the harness can check its own against them.
glm::dmat4 view_matrix(const Camera&);
glm::dmat4 projection_matrix(const Camera&, double aspect);

}  // namespace reference
