#pragma once
// Runs a program as a child process and waits for it: stdin from /dev/null, stdout and
// stderr captured into files (so a chatty child cannot block on a full pipe). Used where
// a tool must run out of process: gnuplot, and the NIR helper that needs Mesa's capture
// environment set before the driver loads.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

struct ChildExit {
  int code = 0;         // exit status, when it exited
  int signal = 0;       // the signal that ended it, when one did
  std::string stdout_text, stderr_text;
  double cpu_ms = 0;    // the child's user + sys time, all its threads

  bool succeeded() const { return signal == 0 && code == 0; }
  std::string how() const;   // "exit 3", "signal 11"
};

// args[0] is the program (a path, or a name looked up on PATH); `environment` replaces
// ours when given. Captured output goes to files in `capture_dir`. An Error (with `stage`) only when the child
// cannot be started or waited for; a child that fails is a ChildExit saying how.
Result<ChildExit> run_child(const std::vector<std::string>& args, const std::filesystem::path& capture_dir,
                            ErrorStage stage,
                            const std::optional<std::vector<std::string>>& environment = std::nullopt);

// A whole file as text ("" when it cannot be read).
std::string read_text_file(const std::filesystem::path& path);

}  // namespace shaderbed
