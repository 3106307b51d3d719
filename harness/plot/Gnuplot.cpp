#include "plot/Gnuplot.h"

#include <unistd.h>

#include <cstdlib>
#include <sstream>

#include <fmt/format.h>

#include "core/ChildProcess.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

constexpr const char* kInstallHint = "install gnuplot-nox (scripts/install-deps)";

bool is_executable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

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

Result<fs::path> find_gnuplot(const std::string& gnuplot) {
  if (gnuplot.find('/') != std::string::npos) {
    if (is_executable_file(gnuplot)) return fs::path(gnuplot);
    return fail(ErrorStage::plot, fmt::format("gnuplot not found at {}: {}", gnuplot, kInstallHint));
  }
  const char* env_path = std::getenv("PATH");
  std::string search = env_path != nullptr ? env_path : "/usr/local/bin:/usr/bin:/bin";
  std::istringstream dirs(search);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / gnuplot;  // empty entry = cwd, as execvp does
    if (is_executable_file(candidate)) return candidate;
  }
  return fail(ErrorStage::plot, fmt::format("{} not found on PATH: {}", gnuplot, kInstallHint));
}

Result<void> run_gnuplot(const std::string& gnuplot, const fs::path& script) {
  auto program = find_gnuplot(gnuplot);
  if (!program) return std::unexpected(program.error());
  auto exit = run_child({program->string(), script.string()}, script.parent_path(), ErrorStage::plot);
  if (!exit) {
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
