#include "core/ChildProcess.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace shaderbed {

std::string ChildExit::how() const {
  return signal != 0 ? "signal " + std::to_string(signal) : "exit " + std::to_string(code);
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Result<ChildExit> run_child(const std::vector<std::string>& args, const std::filesystem::path& capture_dir,
                            ErrorStage stage, const std::optional<std::vector<std::string>>& environment) {
  if (args.empty()) return fail(stage, "no program to run");
  const auto out = capture_dir / "child.stdout", err = capture_dir / "child.stderr";
  std::vector<std::string> argv_text = args, env_text = environment.value_or(std::vector<std::string>{});
  std::vector<char*> argv, envp;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, argv_text[0].c_str(), &actions, nullptr, argv.data(),
                                     environment ? envp.data() : environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return fail(stage, "cannot run " + args[0] + ": " + std::strerror(spawned));

  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) return fail(stage, "lost track of " + args[0] + ": " + std::strerror(errno));
  ChildExit exit;
  const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
  exit.cpu_ms = ms(usage.ru_utime) + ms(usage.ru_stime);
  if (WIFEXITED(status)) exit.code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) exit.signal = WTERMSIG(status);
  exit.stdout_text = read_text_file(out);
  exit.stderr_text = read_text_file(err);
  return exit;
}

}  // namespace shaderbed
