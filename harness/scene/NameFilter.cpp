#include "scene/NameFilter.h"

#include <algorithm>

#include <fmt/format.h>

namespace shaderbed {

bool wanted(const std::vector<std::string>& filter, const std::string& name) {
  return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

Result<void> check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* what) {
  for (const std::string& g : given)
    if (std::find(known.begin(), known.end(), g) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      return fail(ErrorStage::options, fmt::format("unknown {} '{}' (known: {})", what, g, list));
    }
  return {};
}

}  // namespace shaderbed
