#include "plot/Gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

extern char** environ;

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

constexpr const char* kInstallHint = "install gnuplot-nox (scripts/install-deps)";

bool is_executable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
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
    return fail("plot", fmt::format("gnuplot not found at {}: {}", gnuplot, kInstallHint));
  }
  const char* env_path = std::getenv("PATH");
  std::string search = env_path != nullptr ? env_path : "/usr/local/bin:/usr/bin:/bin";
  std::istringstream dirs(search);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / gnuplot;  // empty entry = cwd, as execvp does
    if (is_executable_file(candidate)) return candidate;
  }
  return fail("plot", fmt::format("{} not found on PATH: {}", gnuplot, kInstallHint));
}

Result<void> run_gnuplot(const std::string& gnuplot, const fs::path& script) {
  auto program = find_gnuplot(gnuplot);
  if (!program) return std::unexpected(program.error());

  const fs::path out = script.parent_path() / "gnuplot.stdout", err = script.parent_path() / "gnuplot.stderr";
  std::string program_text = program->string(), script_text = script.string();
  std::vector<char*> argv = {program_text.data(), script_text.data(), nullptr};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program_text.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    return fail("plot", fmt::format("cannot run {}: {} ({})", program_text, std::strerror(spawned), kInstallHint));

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return fail("plot", fmt::format("lost track of {}: {}", program_text, std::strerror(errno)));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};

  const std::string how = WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status))
                                            : fmt::format("signal {}", WTERMSIG(status));
  const std::string line = first_error_line(read_all(err));
  return fail("plot", fmt::format("gnuplot failed ({}): {}", how, line.empty() ? "no message on stderr" : line));
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
