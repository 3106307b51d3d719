#include "run/StoredManifest.h"

#include <filesystem>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/BoundedFile.h"

namespace shaderbed {
namespace fs = std::filesystem;
namespace {

using ordered_json = nlohmann::ordered_json;

Error manifest_error(const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .stage = ErrorStage::stored_images};
}

// "a string", "an array", "null": what a field is instead of what it should be.
std::string type_of(const ordered_json& j) {
  if (j.is_null()) return "null";
  const std::string name = j.type_name();
  return (name == "array" || name == "object" ? "an " : "a ") + name;
}

// The tool fields, in the order they are written.
const std::pair<const char*, std::string ToolVersions::*> kToolFields[] = {
    {"glslang", &ToolVersions::glslang},         {"spirv_tools", &ToolVersions::spirv_tools},
    {"spirv_cross", &ToolVersions::spirv_cross}, {"vulkan_driver", &ToolVersions::vulkan_driver},
    {"gl_driver", &ToolVersions::gl_driver},     {"llvm", &ToolVersions::llvm},
    {"vulkan_device", &ToolVersions::vulkan_device}, {"gl_platform", &ToolVersions::gl_platform}};

// An image's file must stay inside the folder: relative, and without a `..` component
// (an absolute path or `../` would make --against read whatever file the manifest names).
Result<void> check_inside(const std::string& file, const std::string& id, const std::string& path) {
  const auto refuse = [&](const std::string& why) {
    return std::unexpected(manifest_error(path, fmt::format("entry '{}': file '{}' {}", id, file, why)));
  };
  if (file.empty()) return refuse("is empty");
  if (file.find('\0') != std::string::npos) return refuse("holds a NUL byte");
  const fs::path p(file);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory())
    return refuse("is an absolute path: stored images must be inside the manifest's folder");
  for (const fs::path& part : p)
    if (part == "..") return refuse("leaves the manifest's folder ('..'): stored images must be inside it");
  return {};
}

// An optional string field of `object`: absent is "", another type an error. `where`
// names the entry ("entry 'id': "), `parent` the object the key is in ("tools.").
Result<std::string> optional_string(const ordered_json& object, const char* key, const std::string& where,
                                    const std::string& parent, const std::string& path) {
  const auto it = object.find(key);
  if (it == object.end()) return std::string();
  if (!it->is_string())
    return std::unexpected(
        manifest_error(path, fmt::format("{}'{}{}' is {}, not a string", where, parent, key, type_of(*it))));
  return it->get<std::string>();
}

Result<StoredImage> parse_entry(const std::string& id, const ordered_json& entry, const std::string& path) {
  const std::string where = fmt::format("entry '{}': ", id);
  if (!entry.is_object())
    return std::unexpected(manifest_error(path, fmt::format("{}is {}, not an object", where, type_of(entry))));
  const auto file = entry.find("file");
  if (file == entry.end()) return std::unexpected(manifest_error(path, where + "has no file"));
  if (!file->is_string())
    return std::unexpected(manifest_error(path, fmt::format("{}'file' is {}, not a string", where, type_of(*file))));
  StoredImage image{.file = file->get<std::string>()};
  if (auto ok = check_inside(image.file, id, path); !ok) return std::unexpected(ok.error());
  auto scene = optional_string(entry, "scene", where, "", path);
  if (!scene) return std::unexpected(scene.error());
  image.scene = std::move(*scene);
  if (const auto hashes = entry.find("spirv_hash"); hashes != entry.end()) {
    if (!hashes->is_object())
      return std::unexpected(
          manifest_error(path, fmt::format("{}'spirv_hash' is {}, not an object", where, type_of(*hashes))));
    auto vertex = optional_string(*hashes, "vertex", where, "spirv_hash.", path);
    if (!vertex) return std::unexpected(vertex.error());
    auto fragment = optional_string(*hashes, "fragment", where, "spirv_hash.", path);
    if (!fragment) return std::unexpected(fragment.error());
    image.vertex_spirv_hash = std::move(*vertex);
    image.fragment_spirv_hash = std::move(*fragment);
  }
  return image;
}

}  // namespace

Result<StoredManifest> parse_stored_manifest(std::string_view text, const std::string& path) {
  const ordered_json j = ordered_json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return std::unexpected(manifest_error(path, "not a shaderbed stored-images manifest (not a JSON object)"));
  StoredManifest manifest;
  if (const auto schema = j.find("schema"); schema != j.end()) {
    if (!schema->is_number_integer())
      return std::unexpected(manifest_error(path, fmt::format("'schema' is {}, not an integer", type_of(*schema))));
    if (schema->get<long long>() > kStoredImagesSchema)
      return std::unexpected(manifest_error(
          path, fmt::format("schema {} is newer than this shaderbed reads ({})", schema->get<long long>(),
                            kStoredImagesSchema)));
  }
  const auto size = j.find("size");
  if (size == j.end()) return std::unexpected(manifest_error(path, "has no image size ('size')"));
  if (!size->is_number_integer())
    return std::unexpected(manifest_error(path, fmt::format("'size' is {}, not an integer", type_of(*size))));
  const long long pixels = size->get<long long>();
  if (pixels < 1 || pixels > 65536)
    return std::unexpected(manifest_error(path, fmt::format("'size' {} is not an image size", pixels)));
  manifest.size = int(pixels);
  if (const auto tools = j.find("tools"); tools != j.end()) {
    if (!tools->is_object())
      return std::unexpected(manifest_error(path, fmt::format("'tools' is {}, not an object", type_of(*tools))));
    for (const auto& [key, member] : kToolFields) {
      auto value = optional_string(*tools, key, "", "tools.", path);
      if (!value) return std::unexpected(value.error());
      manifest.tools.*member = std::move(*value);
    }
  }
  const auto images = j.find("images");
  if (images == j.end()) return std::unexpected(manifest_error(path, "has no 'images'"));
  if (!images->is_object())
    return std::unexpected(manifest_error(path, fmt::format("'images' is {}, not an object", type_of(*images))));
  for (const auto& [id, entry] : images->items()) {
    auto image = parse_entry(id, entry, path);
    if (!image) return std::unexpected(image.error());
    manifest.images.insert_or_assign(id, std::move(*image));
  }
  return manifest;
}

std::string stored_manifest_text(const StoredManifest& manifest) {
  ordered_json tools = ordered_json::object();
  for (const auto& [key, member] : kToolFields) tools[key] = manifest.tools.*member;
  ordered_json images = ordered_json::object();
  for (const auto& [id, image] : manifest.images)
    images[id] = {{"file", image.file},
                  {"scene", image.scene},
                  {"spirv_hash", {{"vertex", image.vertex_spirv_hash}, {"fragment", image.fragment_spirv_hash}}}};
  const ordered_json j = {
      {"schema", kStoredImagesSchema}, {"size", manifest.size}, {"tools", tools}, {"images", images}};
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

Result<StoredManifest> read_stored_manifest(const std::string& path) {
  auto text = read_bounded_file(path, "the stored-images manifest", ErrorStage::stored_images, kMaxStoredManifestBytes);
  if (!text) return std::unexpected(text.error());
  return parse_stored_manifest(*text, path);
}

}  // namespace shaderbed
