#include "plot/Gnuplot.h"

#include <cerrno>
#include <cstring>
#include <sstream>

#include <fmt/format.h>

#include "core/ChildProcess.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

constexpr const char* kInstallHint = "install gnuplot-nox (scripts/install-deps)";

// The line worth showing: gnuplot prints warnings (e.g. a missing data file) before the
// error that stopped it, so prefer the first line that is not a warning.
std::string first_error_line(const std::string& text) {
  std::string first_nonempty;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (first_nonempty.empty()) first_nonempty = line;
    if (line.find("warning:") == std::string::npos) return line;
  }
  return first_nonempty;
}

}  // namespace

Result<void> run_gnuplot(const std::string& gnuplot, const fs::path& script) {
  // posix_spawnp looks a bare name up on PATH as a shell would (run_child).
  auto exit = run_child({gnuplot, script.string()}, script.parent_path(), ErrorStage::plot);
  if (!exit) {
    if (exit.error().message.ends_with(std::strerror(ENOENT)))
      return fail(ErrorStage::plot, gnuplot.find('/') == std::string::npos
                                        ? fmt::format("{} not found on PATH: {}", gnuplot, kInstallHint)
                                        : fmt::format("gnuplot not found at {}: {}", gnuplot, kInstallHint));
    Error e = std::move(exit.error());
    e.message += fmt::format(" ({})", kInstallHint);
    return std::unexpected(std::move(e));
  }
  if (exit->succeeded()) return {};
  const std::string line = first_error_line(exit->stderr_text);
  return fail(ErrorStage::plot, fmt::format("gnuplot failed ({}): {}", exit->how(), line.empty() ? "no message on stderr" : line));
}

std::string gnuplot_string(std::string_view text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'')
      quoted += "''";
    else if (static_cast<unsigned char>(c) < 0x20)
      quoted += ' ';
    else
      quoted += c;
  }
  return quoted + "'";
}

}  // namespace shaderbed
