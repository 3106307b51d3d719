#include "core/ClosestName.h"

#include <algorithm>

namespace shaderbed {
namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closest_name(std::string_view name, const std::vector<std::string_view>& known) {
  std::string best;
  size_t best_distance = 0;
  for (std::string_view k : known) {
    const size_t d = edit_distance(name, k);
    if (best.empty() || d < best_distance) best = std::string(k), best_distance = d;
  }
  return best_distance <= std::max<size_t>(1, name.size() / 3) ? best : "";
}

std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& known) {
  const std::string near = closest_name(name, known);
  return near.empty() ? "" : " (did you mean '" + near + "'?)";
}

}  // namespace shaderbed
