#pragma once
// What the CLI says when CLI11 refuses the command line: one line "shaderbed: ..." with the
// nearest option, command or allowed value, instead of CLI11's own paragraph.
#include <string>

#include <CLI/CLI.hpp>

namespace shaderbed {

// The line (without "shaderbed: " and the newline) for a parse error of `app`'s command line.
std::string parse_error_line(const CLI::App& app, const CLI::ParseError& error);

}  // namespace shaderbed
