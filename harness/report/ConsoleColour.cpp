#include "report/ConsoleColour.h"

namespace shaderbed {

std::string tinted(std::string_view text, Tint tint, bool on) {
  if (!on || tint == Tint::none || text.empty()) return std::string(text);
  const char* code = tint == Tint::pass ? "\033[32m" : tint == Tint::fail ? "\033[1;31m" : "\033[33m";
  return code + std::string(text) + "\033[0m";
}

}  // namespace shaderbed
