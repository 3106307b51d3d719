#include "core/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace shaderbed {

Result<void> write_file_atomically(const std::string& path, std::string_view bytes, const std::string& what) {
  auto bad = [&](const std::string& why) {
    return std::unexpected(Error{.message = "cannot write " + what + ": " + why, .file = path, .stage = ErrorStage::report});
  };
  std::error_code ec;
  const std::filesystem::path target(path);
  if (const auto parent = target.parent_path(); !parent.empty()) std::filesystem::create_directories(parent, ec);
  // A new file of an unguessable name in the target's folder, created exclusively (mkstemp:
  // O_CREAT | O_EXCL), so nothing planted there is followed or overwritten; renamed over the
  // target, which replaces a symlink at the target rather than the file it points to.
  // A name near NAME_MAX has no room for the suffix: its temporary goes by a short one.
  const std::string stem = target.filename().string().size() + 12 <= 255 ? target.filename().string() : "shaderbed";
  std::string name = (target.parent_path() / ("." + stem + ".tmp.XXXXXX")).string();
  std::vector<char> temporary(name.begin(), name.end());
  temporary.push_back('\0');
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return bad(std::string("cannot create a temporary file beside it: ") + std::strerror(errno));
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);   // as fopen would have made it, not mkstemp's 0600
  bool written = true;
  for (size_t done = 0; written && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    written = n > 0;
    if (written) done += size_t(n);
  }
  written = written && ::fsync(fd) == 0;
  if (::close(fd) != 0 || !written) {
    const std::string why = std::strerror(errno);
    ::unlink(temporary.data());
    return bad("write failed: " + why);
  }
  if (std::rename(temporary.data(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(temporary.data());
    return bad("cannot rename the temporary file over it: " + why);
  }
  return {};
}

}  // namespace shaderbed
