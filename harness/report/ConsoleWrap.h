#pragma once
// Long console lines folded for a terminal: a message of several hundred characters (a
// list of unbound uniforms, a compiler's log line) becomes indented lines of readable width.
#include <string>

namespace shaderbed {

// Lines wider than this are folded; narrower ones stay whole, so a message that fits a
// wide terminal can still be found (and grepped) on one line.
constexpr size_t kConsoleFoldAbove = 160;
// The width folded lines are cut to.
constexpr size_t kConsoleWidth = 100;

// `text` (possibly several lines) with every line wider than kConsoleFoldAbove folded at
// spaces (after "; " where one is near) to kConsoleWidth, continuation lines starting
// with `indent`. The first line's width counts `first_prefix` columns already printed.
std::string fold_for_console(const std::string& text, size_t first_prefix, const std::string& indent);

}  // namespace shaderbed
