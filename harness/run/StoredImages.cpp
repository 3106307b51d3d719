#include "run/StoredImages.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "imageio/ImageIoModule.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

Error stored_error(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = ErrorStage::stored_images};
}

// A stored EXR is read only when it is a regular file no bigger than an uncompressed one
// of the set's size could be: a FIFO would hang the reader, /dev/zero exhaust its memory.
Result<void> check_stored_exr(const std::string& path, int size) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    return std::unexpected(stored_error(path, std::string("cannot read the stored image: ") + std::strerror(errno)));
  if (!S_ISREG(info.st_mode))
    return std::unexpected(stored_error(path, "the stored image is not a regular file (a device, FIFO or folder is refused)"));
  // 5 float channels a pixel, twice over for headers and offset tables, and 1 MiB.
  const uintmax_t limit = uintmax_t(size) * uintmax_t(size) * 5 * 4 * 2 + (uintmax_t(1) << 20);
  if (uintmax_t(info.st_size) > limit)
    return std::unexpected(stored_error(path, fmt::format("the stored image is {0} bytes, more than a {1}x{1} one can be",
                                                          uintmax_t(info.st_size), size)));
  return {};
}

// The canonical form of a folder that may not exist yet, without a trailing separator.
fs::path canonical_folder(const std::string& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  if (ec) p = fs::absolute(dir, ec).lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

// How folder `a` stands to folder `b`: "is", "is inside", "holds", or "" when apart.
std::string folder_relation(const fs::path& a, const fs::path& b) {
  auto ai = a.begin(), bi = b.begin();
  for (; ai != a.end() && bi != b.end(); ++ai, ++bi)
    if (*ai != *bi) return "";
  if (ai == a.end() && bi == b.end()) return "is";
  return ai == a.end() ? "holds" : "is inside";
}

}  // namespace

std::string stored_image_file(const CellResult& r) {
  return (fs::path(r.case_name) / r.variant / r.shape / fmt::format("{}-{}-{}.exr", r.language, r.backend, r.path))
      .string();
}

Result<void> save_stored_image(const std::string& dir, const CellResult& r, const Image& image) {
  const fs::path file = fs::path(dir) / stored_image_file(r);
  std::vector<float> pixels(size_t(image.width) * image.height * 5);
  for (size_t i = 0; i < image.coverage.size(); ++i) {
    for (int c = 0; c < 4; ++c) pixels[i * 5 + c] = image.rgba[i * 4 + c];
    pixels[i * 5 + 4] = image.coverage[i] ? 1.0f : 0.0f;
  }
  return write_image_file(file.string(), image.width, image.height, 5, PixelType::float32, pixels.data());
}

Result<StoredRun> load_stored_run(const std::string& dir, int size) {
  const fs::path file = fs::path(dir) / "manifest.json";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec)))
    return std::unexpected(stored_error(dir, "no manifest.json: not a folder written by shaderbed run --save-images"));
  auto manifest = read_stored_manifest(file.string());
  if (!manifest) return std::unexpected(manifest.error());
  if (manifest->size != size)
    return std::unexpected(stored_error(file.string(), fmt::format("the stored images are {0}x{0}; this run draws "
                                                                   "{1}x{1} (run with --size {0})",
                                                                   manifest->size, size)));
  return StoredRun{.dir = dir, .size = manifest->size, .tools = manifest->tools, .images = std::move(manifest->images)};
}

Result<ReferenceImage> load_stored_image(const StoredRun& run, const std::string& id, const std::string& scene) {
  const auto entry = run.images.find(id);
  if (entry == run.images.end())
    return std::unexpected(stored_error(run.dir, fmt::format("no stored image for {} (the folder has {} images)", id,
                                                             run.images.size())));
  const StoredImage& stored = entry->second;
  const std::string path = (fs::path(run.dir) / stored.file).string();
  if (!stored.scene.empty() && stored.scene != scene)
    return std::unexpected(stored_error(path, "the stored image was drawn with another scene (case parameters, light, "
                                              "ambient or tessellation differ)"));
  if (auto ok = check_stored_exr(path, run.size); !ok) return std::unexpected(ok.error());
  auto pixels = read_image_file(path);
  if (!pixels) return std::unexpected(Error(pixels.error()).in_stage(ErrorStage::stored_images));
  if (pixels->channels != 5 || pixels->width != run.size || pixels->height != run.size)
    return std::unexpected(stored_error(path, fmt::format("expected a {0}x{0} image of 5 channels (RGBA + coverage), "
                                                          "found {1}x{2} with {3}",
                                                          run.size, pixels->width, pixels->height, pixels->channels)));
  ReferenceImage image{pixels->width, pixels->height, {}, {}};
  const size_t n = size_t(image.width) * image.height;
  image.rgba.resize(n * 4);
  image.coverage.resize(n);
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 4; ++c) image.rgba[i * 4 + c] = pixels->values[i * 5 + c];
    image.coverage[i] = pixels->values[i * 5 + 4] > 0.5f ? 1 : 0;
  }
  return image;
}

std::string toolchain_difference(const ToolVersions& stored, const ToolVersions& now) {
  std::string out;
  const auto differ = [&](const char* what, const std::string& a, const std::string& b) {
    if (a != b) out += fmt::format("{}{} {} (stored) vs {}", out.empty() ? "" : "; ", what, a.empty() ? "?" : a, b);
  };
  differ("glslang", stored.glslang, now.glslang);
  differ("SPIRV-Tools", stored.spirv_tools, now.spirv_tools);
  differ("SPIRV-Cross", stored.spirv_cross, now.spirv_cross);
  differ("Vulkan driver", stored.vulkan_driver, now.vulkan_driver);
  differ("GL driver", stored.gl_driver, now.gl_driver);
  differ("LLVM", stored.llvm, now.llvm);
  differ("Vulkan device", stored.vulkan_device, now.vulkan_device);
  // Sets stored before the GL platform was recorded were all drawn on OSMesa.
  differ("GL platform", stored.gl_platform.empty() && !stored.gl_driver.empty() ? "osmesa" : stored.gl_platform,
         now.gl_platform);
  return out;
}

std::vector<std::pair<std::string, std::string>> stored_reference_dirs(const std::string& against_dir,
                                                                       const std::vector<Case>& cases) {
  std::vector<std::pair<std::string, std::string>> dirs;
  if (!against_dir.empty()) dirs.emplace_back(against_dir, "--against");
  else
    for (const Case& c : cases)
      if (!c.reference_images.empty()) dirs.emplace_back(c.reference_images, "case '" + c.name + "'");
  return dirs;
}

Result<void> check_stored_folders(const std::string& out_dir, const std::string& save_images_dir,
                                  const std::vector<std::pair<std::string, std::string>>& judged_by) {
  const auto refuse = [](std::string message) { return fail(ErrorStage::options, std::move(message)); };
  const fs::path out = out_dir.empty() ? fs::path() : canonical_folder(out_dir);
  const fs::path save = save_images_dir.empty() ? fs::path() : canonical_folder(save_images_dir);
  for (const auto& [dir, who] : judged_by) {
    const fs::path judged = canonical_folder(dir);
    // "--against good", or "the reference images of case 'x' (DIR)": what judges the run.
    const std::string what = who == "--against" ? who + " " + dir : fmt::format("the reference images of {} ({})", who, dir);
    if (!save.empty())
      if (const std::string relation = folder_relation(save, judged); !relation.empty())
        return refuse(fmt::format("--save-images {} {} {}: the run would replace the known-good images that judge it "
                                  "(save into another folder)",
                                  save_images_dir, relation, what));
    if (!out.empty())
      if (const std::string relation = folder_relation(out, judged); !relation.empty())
        return refuse(fmt::format("--out {} {} {}: the run's renders would be written over them (write them "
                                  "elsewhere)",
                                  out_dir, relation, what));
  }
  if (!out.empty() && !save.empty())
    if (const std::string relation = folder_relation(out, save); !relation.empty())
      return refuse(fmt::format("--out {} {} the --save-images folder {}: renders and error images would be written "
                                "into the stored set (use two separate folders)",
                                out_dir, relation, save_images_dir));
  return {};
}

Result<StoredReferences> load_stored_references(const std::string& against_dir, int size,
                                                const std::vector<Case>& cases, const ToolVersions& tools) {
  StoredReferences stored;
  for (const auto& named : stored_reference_dirs(against_dir, cases)) {
    const std::string& dir = named.first;
    if (stored.runs.contains(dir)) continue;
    auto run = load_stored_run(dir, size);
    if (!run) return std::unexpected(Error(run.error()).in_stage(against_dir.empty() ? ErrorStage::case_file : ErrorStage::against));
    stored.toolchain_notes[dir] = toolchain_difference(run->tools, tools);
    stored.runs.emplace(dir, std::move(*run));
  }
  return stored;
}

}  // namespace shaderbed
