// Ambient: a constant colour, the ambient term on its own (book §2.5).
#include "reference/Parameters.h"
#include "reference/models/Models.h"

namespace reference {
namespace {

class Ambient final : public LightingModel {
 public:
  explicit Ambient(const glm::dvec3& ambient) : ambient_(ambient) {}

  glm::dvec3 shade(const SurfacePoint&, const ObjectSpaceLighting&) const override { return ambient_; }

 private:
  glm::dvec3 ambient_;
};

}  // namespace

Params ambient_defaults() { return {{"ambient", {0.2, 0.3, 0.4}}}; }

ModelOrError make_ambient(const Params& params) {
  ParameterReader reader("ambient", params);
  const glm::dvec3 ambient = reader.colour("ambient");
  if (auto error = reader.error()) return std::unexpected(*error);
  return std::make_unique<Ambient>(ambient);
}

}  // namespace reference
