#pragma once
// The command line's name filters (--case, --variant, --lang, ...): an empty filter
// selects everything; a name nobody knows is bad input, listed with the known names.
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

bool wanted(const std::vector<std::string>& filter, const std::string& name);

Result<void> check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* what);

}  // namespace shaderbed
