#include "backends/DeviceChoice.h"

#include <algorithm>
#include <cctype>

namespace shaderbed {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Result<size_t> match_device(const std::vector<std::string>& names, const std::string& choice, const std::string& option,
                            const std::string& kind) {
  std::string seen;
  std::vector<size_t> matches;
  const bool is_index = !choice.empty() && std::all_of(choice.begin(), choice.end(), ::isdigit);
  for (size_t i = 0; i < names.size(); ++i) {
    seen += std::string(seen.empty() ? "" : ", ") + std::to_string(i) + ": " + names[i];
    if (is_index ? std::to_string(i) == choice : lower(names[i]).find(lower(choice)) != std::string::npos)
      matches.push_back(i);
  }
  if (matches.size() == 1) return matches.front();
  return fail(ErrorStage::backend, option + " " + choice + (matches.empty() ? " matches none" : " matches several") +
                                       " of the " + kind + " [" + seen + "] ('shaderbed devices' lists them)");
}

}  // namespace shaderbed
