#include "core/AtomicFile.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

namespace shaderbed {

Result<void> write_file_atomically(const std::string& path, std::string_view bytes, const std::string& what) {
  auto bad = [&](const std::string& why) {
    return std::unexpected(Error{.message = "cannot write " + what + ": " + why, .file = path, .stage = ErrorStage::report});
  };
  std::error_code ec;
  if (const auto parent = std::filesystem::path(path).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent, ec);
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (!f) return bad("cannot create " + temporary);
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0 &&
                       ::fsync(fileno(f)) == 0;
  if (std::fclose(f) != 0 || !written) {
    std::remove(temporary.c_str());
    return bad("write failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return bad("cannot rename " + temporary + " over it");
  }
  return {};
}

}  // namespace shaderbed
