#include "core/InstalledTree.h"

#include "core/ThisExecutable.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

// bin_to: the folder's path relative to the install's bin folder (harness/CMakeLists.txt
// derives it from GNUInstallDirs, so a packager's layout is followed).
fs::path installed_dir(const char* bin_to, const char* must_hold) {
  const fs::path self = this_executable();
  if (self.empty()) return {};
  const fs::path dir = (self.parent_path() / bin_to).lexically_normal();
  std::error_code ec;
  return fs::exists(dir / must_hold, ec) ? dir : fs::path();
}

}  // namespace

fs::path installed_data_dir() { return installed_dir(SHADERBED_BIN_TO_DATA, "shaders"); }

fs::path installed_module_dir() { return installed_dir(SHADERBED_BIN_TO_MODULES, "libshaderbed_imageio.so"); }

}  // namespace shaderbed
