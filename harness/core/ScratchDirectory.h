#pragma once
// A private temporary directory (a child process's script, data and captured output),
// removed with everything in it when it goes out of scope.
#include <filesystem>
#include <string>

#include "core/Error.h"

namespace shaderbed {

class ScratchDirectory {
 public:
  // $TMPDIR/shaderbed-<purpose>-XXXXXX; errors have stage `purpose`.
  static Result<ScratchDirectory> create(const std::string& purpose);
  ScratchDirectory(ScratchDirectory&& other) noexcept : path_(std::move(other.path_)) { other.path_.clear(); }
  ScratchDirectory& operator=(ScratchDirectory&&) = delete;
  ScratchDirectory(const ScratchDirectory&) = delete;
  ~ScratchDirectory();

  const std::filesystem::path& path() const { return path_; }

 private:
  explicit ScratchDirectory(std::filesystem::path p) : path_(std::move(p)) {}
  std::filesystem::path path_;
};

}  // namespace shaderbed
