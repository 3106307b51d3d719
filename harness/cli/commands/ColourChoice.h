#pragma once
// --color auto|always|never on the root app (also after the subcommand), and NO_COLOR
// (https://no-color.org): whether the console report on a stream is coloured.
#include <cstdio>

#include <CLI/CLI.hpp>

namespace shaderbed {

void add_colour_option(CLI::App& app);

// True for --color always; for auto (the default), when `stream` is a terminal, TERM is not
// "dumb" and NO_COLOR is unset or empty; false for --color never.
bool colour_on(std::FILE* stream);

}  // namespace shaderbed
