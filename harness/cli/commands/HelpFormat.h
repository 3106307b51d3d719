#pragma once
// `--help` as a Unix user expects it: placeholders that say what a value is (FILE, DIR,
// LIST, N, X) instead of CLI11's type names (TEXT, INT), no build machine's paths in the
// defaults, and text wrapped to the terminal's width.
#include <cstddef>

#include <CLI/CLI.hpp>

namespace shaderbed {

// The width help is wrapped to: $COLUMNS, else the terminal's (stdout), else 100.
size_t help_width();

// Gives `app` and all its subcommands the wrapping formatter and names every option's
// placeholder; call once all options are added.
void format_help(CLI::App& app);

}  // namespace shaderbed
