#pragma once
// `--param name=value[,value...]`: overrides a case parameter from the command line.
#include <string>
#include <utility>
#include <vector>

#include "scene/CaseFile.h"

namespace shaderbed {

Result<std::pair<std::string, std::vector<double>>> parse_parameter(const std::string& text);

// Applies each override to every selected case that declares the parameter (all cases
// when `selected` is empty); an override no selected case declares is an error, and so
// is one whose value count differs from the case's.
Result<void> apply_parameter_overrides(const std::vector<std::string>& overrides, const std::vector<std::string>& selected,
                                       std::vector<Case>& cases);

}  // namespace shaderbed
