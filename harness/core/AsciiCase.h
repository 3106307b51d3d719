#pragma once
// ASCII case folding for identifiers, keywords and file extensions: shader languages and
// effect states compare names byte by byte, never by locale.
#include <string>
#include <string_view>

namespace shaderbed {

inline std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

inline std::string ascii_upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
  return out;
}

}  // namespace shaderbed
