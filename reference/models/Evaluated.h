#pragma once
// One computation for shade() and quantities(): every model in this folder implements
// evaluate(), which computes its colour and, when given a sink, reports the named
// quantities it computes on the way. shade() calls it without a sink; quantities() with
// one, and reports its result as "colour", so that value is shade()'s bit for bit.
#include <string_view>

#include "reference/LightingModel.h"

namespace reference {

// A sink or none: reporting to none does nothing, so evaluate() reads as the formula with
// a report beside each named step. Quantities that only the report needs (an angle the
// model works with as a cosine) are computed under `if (report)`.
class Report {
 public:
  explicit Report(QuantitySink* sink) : sink_(sink) {}
  explicit operator bool() const { return sink_ != nullptr; }

  void scalar(std::string_view name, double value) const {
    if (sink_) sink_->scalar(name, value);
  }
  void direction(std::string_view name, const glm::dvec3& value) const { vector(name, value, VectorKind::direction); }
  void normal(std::string_view name, const glm::dvec3& value) const { vector(name, value, VectorKind::normal); }
  void position(std::string_view name, const glm::dvec3& value) const { vector(name, value, VectorKind::position); }
  void displacement(std::string_view name, const glm::dvec3& value) const {
    vector(name, value, VectorKind::displacement);
  }
  void colour(std::string_view name, const glm::dvec3& value) const { vector(name, value, VectorKind::colour); }

 private:
  void vector(std::string_view name, const glm::dvec3& value, VectorKind kind) const {
    if (sink_) sink_->vector(name, value, kind);
  }
  QuantitySink* sink_;
};

class EvaluatedModel : public LightingModel {
 public:
  glm::dvec3 shade(const SurfacePoint& point, const ObjectSpaceLighting& lighting) const final {
    return evaluate(point, lighting, Report(nullptr));
  }
  void quantities(const SurfacePoint& point, const ObjectSpaceLighting& lighting, QuantitySink& sink) const final {
    const Report report(&sink);
    report.colour("colour", evaluate(point, lighting, report));
  }

 private:
  virtual glm::dvec3 evaluate(const SurfacePoint& point, const ObjectSpaceLighting& lighting,
                              Report report) const = 0;
};

}  // namespace reference
