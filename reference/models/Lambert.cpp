// Lambert: I = D max(0, N·L) with the directional light (book §2.1, shaders §3.5-3.6).
// The light colour is 1 and there is no 1/pi, as in the book.
#include <algorithm>

#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"

namespace reference {
namespace {

class Lambert final : public EvaluatedModel {
 public:
  explicit Lambert(const glm::dvec3& diffuse) : diffuse_(diffuse) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting, Report report) const override {
    report.normal("N", point.normal);
    report.direction("L", lighting.light_direction);
    const double n_dot_l = glm::dot(point.normal, lighting.light_direction);
    report.scalar("N·L", n_dot_l);
    const double lit = std::max(0.0, n_dot_l);
    report.scalar("sat(N·L)", lit);
    const glm::dvec3 diffuse = diffuse_ * lit;
    report.colour("diffuse", diffuse);
    return diffuse;
  }

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
