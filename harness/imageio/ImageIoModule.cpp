#include "imageio/ImageIoModule.h"

#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <mutex>

#include "core/AtomicFile.h"
#include "core/InstalledTree.h"
#include "core/ThisExecutable.h"
#include "imageio/ExrHeaderScan.h"
#include "imageio/ModuleAbi.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

constexpr const char* kModuleName = "libshaderbed_imageio.so";

struct LoadedModule {
  const ShaderbedImageIo* table = nullptr;
  std::string error;
};

// Next to the running binary first (a copied tree), then an installed tree's lib/shaderbed,
// else where the build put it.
std::vector<fs::path> module_candidates() {
  std::vector<fs::path> candidates;
  if (const fs::path self = this_executable(); !self.empty()) candidates.push_back(self.parent_path() / kModuleName);
  if (const fs::path installed = installed_module_dir(); !installed.empty()) candidates.push_back(installed / kModuleName);
  candidates.push_back(SHADERBED_IMAGEIO_MODULE);
  return candidates;
}

const LoadedModule& image_module() {
  static LoadedModule loaded;
  static std::once_flag once;
  std::call_once(once, [] {
    std::string tried;
    for (const fs::path& candidate : module_candidates()) {
      void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        tried += std::string(tried.empty() ? "" : "; ") + ::dlerror();
        continue;
      }
      // Never dlclosed: OpenImageIO keeps threads and plugins of its own.
      using Entry = const ShaderbedImageIo* (*)();
      if (auto entry = reinterpret_cast<Entry>(::dlsym(handle, "shaderbed_image_io_v3"))) {
        loaded.table = entry();
        return;
      }
      tried += std::string(tried.empty() ? "" : "; ") + candidate.string() + " has no shaderbed_image_io_v3";
    }
    loaded.error = "cannot load the image I/O module " + std::string(kModuleName) + ": " + tried;
  });
  return loaded;
}

Error image_error(const std::string& message, const std::string& path) {
  return Error{.message = message, .file = path, .stage = ErrorStage::image};
}

}  // namespace

Result<void> write_image_file(const std::string& path, int width, int height, int channels, PixelType type,
                              const void* pixels) {
  const LoadedModule& module = image_module();
  if (!module.table) return std::unexpected(image_error(module.error, path));
  std::array<char, 1024> error{};
  unsigned char* bytes = nullptr;
  size_t size = 0;
  if (module.table->encode(path.c_str(), width, height, channels, type == PixelType::float32, pixels, &bytes, &size,
                           error.data(), error.size()) != 0)
    return std::unexpected(image_error(error.data(), path));
  // Every write checked and flushed (a full disk is an error, not a short file), through
  // an exclusively created temporary renamed into place: a killed run, or two runs
  // writing the same --out, never leave half an image.
  auto written = write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes), size), "image");
  module.table->free_bytes(bytes);
  if (!written) return std::unexpected(image_error(written.error().message, path));
  return {};
}

Result<ImagePixels> read_image_file(const std::string& path) {
  const LoadedModule& module = image_module();
  if (!module.table) return std::unexpected(image_error(module.error, path));
  if (auto ok = check_exr_header_sizes(path); !ok) return std::unexpected(ok.error());
  std::array<char, 1024> error{};
  ImagePixels image;
  float* pixels = nullptr;
  if (module.table->read(path.c_str(), &image.width, &image.height, &image.channels, &pixels, error.data(),
                         error.size()) != 0)
    return std::unexpected(image_error(error.data(), path));
  image.values.assign(pixels, pixels + size_t(image.width) * image.height * image.channels);
  module.table->free_pixels(pixels);
  return image;
}

Result<ImageFileLevels> read_image_levels(const std::string& path, bool all_levels) {
  const LoadedModule& module = image_module();
  if (!module.table) return std::unexpected(image_error(module.error, path));
  if (auto ok = check_exr_header_sizes(path); !ok) return std::unexpected(ok.error());
  ImageFileLevels file;
  for (int level = 0, levels = 1; level < (all_levels ? levels : 1); ++level) {
    std::array<char, 1024> error{};
    ImagePixels image;
    float* pixels = nullptr;
    int eight_bit = 0;
    if (module.table->read_level(path.c_str(), level, &image.width, &image.height, &image.channels, &levels,
                                 &eight_bit, &pixels, error.data(), error.size()) != 0)
      return std::unexpected(image_error(error.data(), path));
    image.values.assign(pixels, pixels + size_t(image.width) * image.height * image.channels);
    module.table->free_pixels(pixels);
    if (level == 0) file.eight_bit = eight_bit != 0;
    file.levels.push_back(std::move(image));
  }
  return file;
}

}  // namespace shaderbed
