#include "scene/NameFilter.h"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/ClosestName.h"

namespace shaderbed {

bool wanted(const std::vector<std::string>& filter, const std::string& name) {
  return filter.empty() || std::find(filter.begin(), filter.end(), name) != filter.end();
}

Result<void> check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* what) {
  for (const std::string& g : given)
    if (std::find(known.begin(), known.end(), g) == known.end()) {
      const std::string near = closest_name(g, std::vector<std::string_view>(known.begin(), known.end()));
      if (!near.empty()) return fail(ErrorStage::options, fmt::format("unknown {} '{}' (did you mean '{}'?)", what, g, near));
      return fail(ErrorStage::options, fmt::format("unknown {} '{}' (known: {})", what, g, fmt::join(known, ", ")));
    }
  return {};
}

}  // namespace shaderbed
