#include "reference/Parameters.h"

namespace reference {

const std::vector<double>* ParameterReader::find(const std::string& name, size_t min_count, size_t max_count,
                                                 std::string_view expected) {
  const auto found = params_.find(name);
  if (found == params_.end()) {
    problems_.push_back(model_ + ": missing parameter '" + name + "'");
    return nullptr;
  }
  const size_t count = found->second.size();
  if (count < min_count || count > max_count) {
    problems_.push_back(model_ + ": parameter '" + name + "' needs " + std::string(expected) + ", got " +
                        std::to_string(count) + " value(s)");
    return nullptr;
  }
  return &found->second;
}

glm::dvec3 ParameterReader::colour(const std::string& name) {
  const std::vector<double>* values = find(name, 3, 4, "3 or 4 values (a colour)");
  return values ? glm::dvec3((*values)[0], (*values)[1], (*values)[2]) : glm::dvec3(0.0);
}

double ParameterReader::scalar(const std::string& name) {
  const std::vector<double>* values = find(name, 1, 1, "1 value");
  return values ? (*values)[0] : 0.0;
}

std::optional<std::string> ParameterReader::error() const {
  if (problems_.empty()) return std::nullopt;
  std::string joined;
  for (const std::string& problem : problems_) joined += (joined.empty() ? "" : "; ") + problem;
  return joined;
}

}  // namespace reference
