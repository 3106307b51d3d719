// Lambert: I = D max(0, N·L) with the directional light (book §2.1, shaders §3.5-3.6).
// The light colour is 1 and there is no 1/pi, as in the book.
#include <algorithm>

#include "reference/Parameters.h"
#include "reference/models/Models.h"

namespace reference {
namespace {

class Lambert final : public LightingModel {
 public:
  explicit Lambert(const glm::dvec3& diffuse) : diffuse_(diffuse) {}

  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const override {
    return diffuse_ * std::max(0.0, glm::dot(point.normal, lighting.light_direction));
  }

 private:
  glm::dvec3 diffuse_;
};

}  // namespace

Params lambert_defaults() { return {{"diffuse", {1, 1, 1}}}; }

ModelOrError make_lambert(const Params& params) {
  ParameterReader reader("lambert", params);
  const glm::dvec3 diffuse = reader.colour("diffuse");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Lambert>(diffuse);
}

}  // namespace reference
