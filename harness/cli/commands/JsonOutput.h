#pragma once
// `--json -` for the commands that print a table as they go (stats, sweep, hard): standard
// output then carries the JSON alone, so a pipe into `jq` works; everything else the
// command prints, its own lines and its libraries', goes to standard error.
#include <string>

#include "core/Error.h"

namespace shaderbed {

class JsonOutput {
 public:
  // With "-", file descriptor 1 points at standard error until the destructor; the real
  // standard output is kept for write().
  explicit JsonOutput(std::string path);
  ~JsonOutput();
  JsonOutput(const JsonOutput&) = delete;
  JsonOutput& operator=(const JsonOutput&) = delete;

  bool wanted() const { return !path_.empty(); }
  bool on_stdout() const { return kept_stdout_ >= 0; }
  // The file, written whole (a temporary renamed over it), or the kept standard output.
  Result<void> write(const std::string& text, const std::string& what) const;

 private:
  std::string path_;
  int kept_stdout_ = -1;
};

}  // namespace shaderbed
