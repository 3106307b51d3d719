#include "reference/Parameters.h"

#include <algorithm>

namespace reference {

const std::vector<double>* ParameterReader::find(const std::string& name, size_t min_count, size_t max_count,
                                                 std::string_view expected) {
  const auto found = params_.find(name);
  if (found == params_.end()) {
    problems_.push_back(model_ + ": missing parameter '" + name + "'");
    unreadable_.push_back(name);
    return nullptr;
  }
  const size_t count = found->second.size();
  if (count < min_count || count > max_count) {
    problems_.push_back(model_ + ": parameter '" + name + "' needs " + std::string(expected) + ", got " +
                        std::to_string(count) + " value(s)");
    unreadable_.push_back(name);
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

glm::dvec2 ParameterReader::pair(const std::string& name) {
  const std::vector<double>* values = find(name, 2, 2, "2 values");
  return values ? glm::dvec2((*values)[0], (*values)[1]) : glm::dvec2(0.0);
}

glm::dvec3 ParameterReader::triple(const std::string& name) {
  const std::vector<double>* values = find(name, 3, 3, "3 values");
  return values ? glm::dvec3((*values)[0], (*values)[1], (*values)[2]) : glm::dvec3(0.0);
}

void ParameterReader::require(const std::string& name, bool ok, std::string_view condition) {
  if (ok || std::ranges::find(unreadable_, name) != unreadable_.end()) return;
  problems_.push_back(model_ + ": parameter '" + name + "' " + std::string(condition));
}

std::optional<std::string> ParameterReader::error() const {
  if (problems_.empty()) return std::nullopt;
  std::string joined;
  for (const std::string& problem : problems_) joined += (joined.empty() ? "" : "; ") + problem;
  return joined;
}

}  // namespace reference
