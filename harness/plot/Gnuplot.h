#pragma once
// gnuplot as a child process: run one script, turn a failure into an Error
// (stage "plot") that says what to install or what gnuplot complained about.
#include <filesystem>
#include <string>
#include <string_view>

#include "core/Error.h"

namespace shaderbed {

// Runs `gnuplot script` with stdin from /dev/null (`gnuplot` is a name looked up on PATH,
// or a path when it contains '/'); fails when gnuplot cannot be found or started, or exits non-zero (the message carries its first error line on stderr).
Result<void> run_gnuplot(const std::string& gnuplot, const std::filesystem::path& script);

// A gnuplot single-quoted string literal for arbitrary text. Inside single quotes
// gnuplot interprets no escapes (backslashes, '@' macros and '"' are literal) except ''
// for one quote; control characters (line breaks) become spaces since a literal cannot span lines.
std::string gnuplot_string(std::string_view text);

}  // namespace shaderbed
