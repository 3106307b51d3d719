#include "core/BoundedFile.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace shaderbed {
namespace {

// The file's size once it passed the checks.
Result<size_t> checked_size(const std::string& path, const std::string& what, ErrorStage stage, size_t limit) {
  const auto error = [&](std::string message) {
    return std::unexpected(Error{.message = std::move(message), .file = path, .stage = stage});
  };
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return error("cannot read " + what + ": " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) return error(what + " is not a regular file (a device, FIFO or folder is refused)");
  if (size_t(info.st_size) > limit)
    return error(what + " is " + std::to_string(info.st_size) + " bytes, over the " + std::to_string(limit >> 20) +
                 " MiB it may have");
  return size_t(info.st_size);
}

}  // namespace

Result<void> check_bounded_file(const std::string& path, const std::string& what, ErrorStage stage, size_t limit) {
  auto size = checked_size(path, what, stage, limit);
  if (!size) return std::unexpected(size.error());
  return {};
}

Result<std::string> read_bounded_file(const std::string& path, const std::string& what, ErrorStage stage,
                                      size_t limit) {
  auto size = checked_size(path, what, stage, limit);
  if (!size) return std::unexpected(size.error());
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::unexpected(Error{.message = "cannot read " + what, .file = path, .stage = stage});
  std::string text(*size, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(size_t(in.gcount()));
  return text;
}

}  // namespace shaderbed
