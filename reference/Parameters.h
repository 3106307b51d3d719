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

  // Every problem found so far, as "model: problem; model: problem", or nothing.
  std::optional<std::string> error() const;

 private:
  const std::vector<double>* find(const std::string& name, size_t min_count, size_t max_count,
                                  std::string_view expected);

  std::string model_;
  const Params& params_;
  std::vector<std::string> problems_;
};

}  // namespace reference
