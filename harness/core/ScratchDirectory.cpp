#include "core/ScratchDirectory.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace shaderbed {

Result<ScratchDirectory> ScratchDirectory::create(const std::string& purpose) {
  std::error_code ec;
  std::filesystem::path base = std::filesystem::temp_directory_path(ec);
  if (ec) base = "/tmp";
  std::string pattern = (base / ("shaderbed-" + purpose + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    return fail(ErrorStage::none, purpose + ": cannot create a temporary directory under " + base.string() + ": " + std::strerror(errno));
  return ScratchDirectory(std::filesystem::path(pattern));
}

ScratchDirectory::~ScratchDirectory() {
  if (path_.empty()) return;
  std::error_code ec;  // best effort: a leftover temp dir is not worth failing over
  std::filesystem::remove_all(path_, ec);
}

}  // namespace shaderbed
