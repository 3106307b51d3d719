#include "run/StoredImages.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "imageio/ImageIoModule.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

using ordered_json = nlohmann::ordered_json;

Error stored_error(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = ErrorStage::stored_images};
}

ordered_json tools_json(const ToolVersions& t) {
  return {{"glslang", t.glslang}, {"spirv_tools", t.spirv_tools}, {"spirv_cross", t.spirv_cross},
          {"vulkan_driver", t.vulkan_driver}, {"gl_driver", t.gl_driver}, {"llvm", t.llvm},
          {"vulkan_device", t.vulkan_device}};
}

ToolVersions tools_of(const ordered_json& j) {
  ToolVersions t;
  const auto get = [&](const char* key, std::string& out) {
    if (j.contains(key) && j[key].is_string()) out = j[key].get<std::string>();
  };
  get("glslang", t.glslang);
  get("spirv_tools", t.spirv_tools);
  get("spirv_cross", t.spirv_cross);
  get("vulkan_driver", t.vulkan_driver);
  get("gl_driver", t.gl_driver);
  get("llvm", t.llvm);
  get("vulkan_device", t.vulkan_device);
  return t;
}

// The manifest as it is on disk, or an empty one when there is none yet.
Result<ordered_json> read_manifest(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return ordered_json::object();
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  ordered_json j = ordered_json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("images") || !j["images"].is_object())
    return std::unexpected(stored_error(file.string(), "not a shaderbed stored-images manifest"));
  return j;
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

Result<void> write_stored_manifest(const std::string& dir, const RunReport& report, int size) {
  const fs::path file = fs::path(dir) / "manifest.json";
  auto existing = read_manifest(file);
  if (!existing) return std::unexpected(existing.error());
  ordered_json manifest = std::move(*existing);
  if (manifest.contains("size") && manifest["size"] != size)
    return std::unexpected(stored_error(file.string(), fmt::format("the folder holds {0}x{0} images; this run drew "
                                                                   "{1}x{1} (save into another folder)",
                                                                   manifest["size"].get<int>(), size)));
  manifest["schema"] = kStoredImagesSchema;
  manifest["size"] = size;
  manifest["tools"] = tools_json(report.tools);
  if (!manifest.contains("images")) manifest["images"] = ordered_json::object();
  for (const CellResult& r : report.results) {
    if (r.artefacts.stored_exr.empty()) continue;
    manifest["images"][r.id()] = {{"file", stored_image_file(r)},
                                  {"scene", r.scene_hash},
                                  {"spirv_hash", {{"vertex", r.vertex_spirv_hash}, {"fragment", r.fragment_spirv_hash}}}};
  }
  return write_file_atomically(file.string(), manifest.dump(2) + "\n", "the stored-images manifest");
}

Result<StoredRun> load_stored_run(const std::string& dir, int size) {
  const fs::path file = fs::path(dir) / "manifest.json";
  std::error_code ec;
  if (!fs::exists(file, ec))
    return std::unexpected(stored_error(dir, "no manifest.json: not a folder written by shaderbed run --save-images"));
  auto manifest = read_manifest(file);
  if (!manifest) return std::unexpected(manifest.error());
  const ordered_json& m = *manifest;
  StoredRun run{.dir = dir, .size = m.value("size", 0), .tools = tools_of(m.value("tools", ordered_json::object()))};
  if (run.size != size)
    return std::unexpected(stored_error(file.string(), fmt::format("the stored images are {0}x{0}; this run draws "
                                                                   "{1}x{1} (run with --size {0})",
                                                                   run.size, size)));
  for (const auto& [id, entry] : m["images"].items()) {
    if (!entry.is_object() || !entry.contains("file") || !entry["file"].is_string())
      return std::unexpected(stored_error(file.string(), "entry '" + id + "' has no file"));
    StoredImage image{.file = entry["file"].get<std::string>(), .scene = entry.value("scene", std::string())};
    if (entry.contains("spirv_hash") && entry["spirv_hash"].is_object()) {
      image.vertex_spirv_hash = entry["spirv_hash"].value("vertex", std::string());
      image.fragment_spirv_hash = entry["spirv_hash"].value("fragment", std::string());
    }
    run.images.emplace(id, std::move(image));
  }
  return run;
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
  return out;
}

Result<StoredReferences> load_stored_references(const std::string& against_dir, int size,
                                                const std::vector<Case>& cases, const ToolVersions& tools) {
  StoredReferences stored;
  std::vector<std::string> dirs;
  if (!against_dir.empty()) dirs.push_back(against_dir);
  else
    for (const Case& c : cases)
      if (!c.reference_images.empty()) dirs.push_back(c.reference_images);
  for (const std::string& dir : dirs) {
    if (stored.runs.contains(dir)) continue;
    auto run = load_stored_run(dir, size);
    if (!run) return std::unexpected(Error(run.error()).in_stage(against_dir.empty() ? ErrorStage::case_file : ErrorStage::against));
    stored.toolchain_notes[dir] = toolchain_difference(run->tools, tools);
    stored.runs.emplace(dir, std::move(*run));
  }
  return stored;
}

}  // namespace shaderbed
