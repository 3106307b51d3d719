#pragma once
// The first line of a message, where a report has room for one.
#include <string>

namespace shaderbed {

inline std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace shaderbed
