#pragma once
// Runs a shell command line (the CLI binary, usually) and returns its exit status (-1 when
// it did not exit normally) and its stdout and stderr together, for the tests that check
// what a user sees.
#include <sys/wait.h>

#include <cstdio>
#include <string>
#include <utility>

namespace shaderbed::test {

inline std::pair<int, std::string> run_shell(const std::string& command_line) {
  const std::string cmd = command_line + " 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "popen failed"};
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

#ifdef SHADERBED_BINARY
// The shaderbed CLI (the build's binary) with `args`, for the areas whose tests run it.
inline std::pair<int, std::string> shaderbed_cli(const std::string& args) {
  return run_shell(std::string(SHADERBED_BINARY) + " " + args);
}
#endif

}  // namespace shaderbed::test
