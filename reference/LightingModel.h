#pragma once
// The interface every lighting model implements, and what it is given. A model is built
// once from its parameters (so a missing parameter is an error before any rendering)
// and then evaluated per vertex or per pixel. Everything is in object space, as in the
// book's shaders: the normal is never transformed; lights and eye are moved instead.
#include <expected>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace reference {

// A point on the surface, in object space.
struct SurfacePoint {
  glm::dvec3 position;
  glm::dvec3 normal;   // unit length
  glm::dvec3 tangent;  // as given or interpolated, not normalised: models that need it do
  glm::dvec2 uv;
};

// The scene's lights and eye, moved into object space by the inverse world matrix.
// Models choose which light they use: the directional light (Lambert, Phong), the point
// light (attenuation, Warn spotlights), or both.
struct ObjectSpaceLighting {
  glm::dvec3 light_direction;  // unit vector toward the directional light
  glm::dvec3 light_position;   // point light position
  glm::dvec3 eye_position;
  // Set only under Perturbation::interpolated_light_eye: L and V as a shader that
  // normalised them per vertex receives them per pixel (interpolated, not renormalised).
  // Models take them as they are instead of building them from the positions; a point
  // light's distance still comes from light_position.
  std::optional<glm::dvec3> to_light;
  std::optional<glm::dvec3> to_eye;
};

// What a reported vector is, so that it can be carried into world space as a shader
// working there would have it (ModelQuantities.h).
enum class VectorKind {
  direction,     // a direction or a sum of directions (L, V, H, L + V, X, ...): turned by the
                 // world matrix, length kept
  normal,        // a surface normal: turned by the world matrix's inverse transpose, length kept
  position,      // a point (P, eye_position): W (v, 1)
  displacement,  // a difference of points (light_position − P): W (v, 0)
  colour,        // RGB: the same in every space
};

// Receives a model's named intermediate quantities at one point (N·L, N·H, D, F, G, ...),
// named as a shader author would name them; docs/models.md, "Named quantities".
class QuantitySink {
 public:
  virtual ~QuantitySink() = default;
  virtual void scalar(std::string_view name, double value) = 0;
  virtual void vector(std::string_view name, const glm::dvec3& value, VectorKind kind) = 0;
};

class LightingModel {
 public:
  virtual ~LightingModel() = default;
  // Outgoing colour, unclamped: a model that exceeds 1 must be seen to do so.
  virtual glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const = 0;
  // The same point as shade(), reporting what the model computes on the way, the last
  // quantity being "colour", bit for bit shade()'s result (the library's models compute
  // both in one function). The default reports nothing: a model built outside the library
  // (an SH case's radiance) has no named quantities.
  virtual void quantities(const SurfacePoint&, const ObjectSpaceLighting&, QuantitySink&) const {}
};

using ModelOrError = std::expected<std::unique_ptr<const LightingModel>, std::string>;

}  // namespace reference
