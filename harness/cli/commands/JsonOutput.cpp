#include "cli/commands/JsonOutput.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <unistd.h>

#include "core/AtomicFile.h"

namespace shaderbed {

JsonOutput::JsonOutput(std::string path) : path_(std::move(path)) {
  if (path_ != "-") return;
  std::fflush(stdout);
  kept_stdout_ = dup(STDOUT_FILENO);
  if (kept_stdout_ >= 0) dup2(STDERR_FILENO, STDOUT_FILENO);
}

JsonOutput::~JsonOutput() {
  if (kept_stdout_ < 0) return;
  std::fflush(stdout);
  dup2(kept_stdout_, STDOUT_FILENO);
  close(kept_stdout_);
}

Result<void> JsonOutput::write(const std::string& text, const std::string& what) const {
  if (!on_stdout()) return write_file_atomically(path_, text, what);
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(kept_stdout_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return fail(ErrorStage::report, "cannot write " + what + " to standard output: " + std::strerror(errno));
    done += static_cast<size_t>(n);
  }
  return {};
}

}  // namespace shaderbed
