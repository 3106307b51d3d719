#pragma once
// ANSI colour for the console report's verdicts, on only when the CLI says the reader sees
// it (a terminal, no NO_COLOR, --color): green passes, red failures, yellow errors and
// known failures.
#include <string>
#include <string_view>

namespace shaderbed {

enum class Tint { none, pass, fail, warn };

// `text` wrapped in the tint's escape codes when `on`, else as it is.
std::string tinted(std::string_view text, Tint tint, bool on);

}  // namespace shaderbed
