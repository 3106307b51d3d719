// Ambient: a constant colour, the ambient term on its own (book §2.5).
#include "reference/Parameters.h"
#include "reference/models/Evaluated.h"
#include "reference/models/Models.h"

namespace reference {
namespace {

class Ambient final : public EvaluatedModel {
 public:
  explicit Ambient(const glm::dvec3& ambient) : ambient_(ambient) {}

 private:
  glm::dvec3 evaluate(const SurfacePoint&, const ObjectSpaceLighting&, Report report) const override {
    report.colour("ambient", ambient_);
    return ambient_;
  }

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
