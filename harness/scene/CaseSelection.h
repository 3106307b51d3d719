#pragma once
// The case files a --case filter selects, loaded. Only the selected files are read, so
// one broken case does not block the others; a name no file has is an error listing the
// names there are.
#include <string>
#include <vector>

#include "scene/CaseFile.h"

namespace shaderbed {

Result<std::vector<Case>> load_selected_cases(const std::string& directory, const std::vector<std::string>& filter);

}  // namespace shaderbed
