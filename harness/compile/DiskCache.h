#pragma once
// A folder of cache entries, one file each, shared by concurrent workers and concurrent
// processes. An entry is written to a private temporary file in the same folder and
// renamed into place, so a reader sees either no entry or a whole one, never a partial
// write; two writers of one entry both write the same bytes and the last rename wins.
// Best-effort: a folder that cannot be created or written means no caching, not an error.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/Fnv1a.h"

namespace shaderbed {

// A whole file's bytes; nullopt when it cannot be read.
std::optional<std::string> read_file_bytes(const std::filesystem::path& path);

class DiskCache {
 public:
  explicit DiskCache(std::filesystem::path dir) : dir_(std::move(dir)) {}
  const std::filesystem::path& dir() const { return dir_; }

  // The entry's bytes; nullopt when there is none or it cannot be read.
  std::optional<std::string> load(const std::string& name) const;
  // Writes the entry atomically; false when it could not be written.
  bool store(const std::string& name, std::string_view bytes) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace shaderbed
