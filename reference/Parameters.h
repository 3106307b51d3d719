#pragma once
// Reads a model's parameters by name and collects every problem, so one error message
// names the model and all the parameters it is missing.
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reference/Reference.h"

namespace reference {

class ParameterReader {
 public:
  ParameterReader(std::string_view model, const Params& params) : model_(model), params_(params) {}

  // An RGB colour: three values, or four with the fourth (alpha) ignored.
  glm::dvec3 colour(const std::string& name);
  // One value.
  double scalar(const std::string& name);
  // Exactly two / three values (roughness_xy, attenuation): not colours, so no alpha.
  glm::dvec2 pair(const std::string& name);
  glm::dvec3 triple(const std::string& name);

  // Records "model: parameter 'name' <condition>" unless `ok`: for values outside the
  // domain where the model's equation is defined, e.g. a roughness of 0. Skipped when the
  // parameter itself is missing or malformed (that problem is already recorded).
  void require(const std::string& name, bool ok, std::string_view condition);

  // Every problem found so far, as "model: problem; model: problem", or nothing.
  std::optional<std::string> error() const;

 private:
  const std::vector<double>* find(const std::string& name, size_t min_count, size_t max_count,
                                  std::string_view expected);

  std::string model_;
  const Params& params_;
  std::vector<std::string> problems_;
  std::vector<std::string> unreadable_;  // names already reported missing or malformed
};

}  // namespace reference
