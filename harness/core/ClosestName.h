#pragma once
// "Did you mean": the known name nearest a mistyped one, for case keys, binding names,
// scene quantities, models and command-line options alike.
#include <string>
#include <string_view>
#include <vector>

namespace shaderbed {

// The known name within a third of the word's edits of `name` (at least one), the nearest
// first; "" when none is that close ("tolerence" -> "tolerance", not "mode" -> "model").
std::string closest_name(std::string_view name, const std::vector<std::string_view>& known);

// " (did you mean 'x'?)" when a name is close, else "".
std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& known);

}  // namespace shaderbed
