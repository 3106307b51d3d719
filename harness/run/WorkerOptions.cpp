#include "run/WorkerOptions.h"

#include <optional>

#include <nlohmann/json.hpp>

namespace shaderbed {

using json = nlohmann::json;

// Field by field, so a renamed member is a compile error here rather than a silent default.
void to_json(json& j, const SuiteSelection& s) {
  j = {{"cases_dir", s.cases_dir}, {"cases", s.cases},         {"variants", s.variants},
       {"backends", s.backends},   {"languages", s.languages}, {"shapes", s.shapes},
       {"params", s.params},       {"shard", s.shard},         {"paths", s.paths}};
}
void from_json(const json& j, SuiteSelection& s) {
  j.at("cases_dir").get_to(s.cases_dir);
  j.at("cases").get_to(s.cases);
  j.at("variants").get_to(s.variants);
  j.at("backends").get_to(s.backends);
  j.at("languages").get_to(s.languages);
  j.at("shapes").get_to(s.shapes);
  j.at("params").get_to(s.params);
  j.at("shard").get_to(s.shard);
  j.at("paths").get_to(s.paths);
}

void to_json(json& j, const CellSettings& c) {
  j = {{"size", c.size},
       {"out_dir", c.out_dir},
       {"save_images_dir", c.save_images_dir},
       {"against_dir", c.against_dir},
       {"warmup", c.timing.warmup},
       {"runs", c.timing.runs},
       {"mesh_slices", c.mesh_slices},
       {"relaxed_precision", c.relaxed_precision},
       {"per_pixel_reference", c.per_pixel_reference},
       {"unused_binding_warnings", c.unused_binding_warnings},
       {"twin", c.twin},
       {"keep_images", c.keep_images}};
}
void from_json(const json& j, CellSettings& c) {
  j.at("size").get_to(c.size);
  j.at("out_dir").get_to(c.out_dir);
  j.at("save_images_dir").get_to(c.save_images_dir);
  j.at("against_dir").get_to(c.against_dir);
  j.at("warmup").get_to(c.timing.warmup);
  j.at("runs").get_to(c.timing.runs);
  j.at("mesh_slices").get_to(c.mesh_slices);
  j.at("relaxed_precision").get_to(c.relaxed_precision);
  j.at("per_pixel_reference").get_to(c.per_pixel_reference);
  j.at("keep_images").get_to(c.keep_images);
  j.at("unused_binding_warnings").get_to(c.unused_binding_warnings);
  j.at("twin").get_to(c.twin);
}

void to_json(json& j, const ProcessSettings& p) {
  j = {{"cache_root", p.caches.root},
       {"driver_cache", p.caches.driver},
       {"compile_cache", p.caches.compile},
       {"vulkan_device", p.vulkan_device},
       {"gl_platform", p.gl_platform.platform},
       {"gl_device", p.gl_platform.device}};
}
void from_json(const json& j, ProcessSettings& p) {
  j.at("cache_root").get_to(p.caches.root);
  j.at("driver_cache").get_to(p.caches.driver);
  j.at("compile_cache").get_to(p.caches.compile);
  j.at("vulkan_device").get_to(p.vulkan_device);
  j.at("gl_platform").get_to(p.gl_platform.platform);
  j.at("gl_device").get_to(p.gl_platform.device);
}

WorkerOptions worker_options(const RunOptions& o) {
  // Decided here, before any worker starts, so a full cache folder's note is printed once.
  cache_root_writable();
  return {o.select, cell_settings(o), {cache_settings(), chosen_vulkan_device(), chosen_gl_platform()}};
}

namespace {

// JSON text must be UTF-8, but a path is bytes (`--out` in a Latin-1 folder): every
// string goes as its bytes, each one code point U+0000..U+00FF, and comes back byte for
// byte, so a worker writes exactly where the user asked.
std::string bytes_as_code_points(const std::string& bytes) {
  std::string text;
  for (const unsigned char b : bytes) {
    if (b < 0x80) {
      text += char(b);
    } else {
      text += char(0xC0 | (b >> 6));
      text += char(0x80 | (b & 0x3F));
    }
  }
  return text;
}

std::optional<std::string> code_points_as_bytes(const std::string& text) {
  std::string bytes;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = text[i];
    if (c < 0x80) {
      bytes += char(c);
    } else if ((c == 0xC2 || c == 0xC3) && i + 1 < text.size() && (text[i + 1] & 0xC0) == 0x80) {
      bytes += char(((c & 0x03) << 6) | (text[++i] & 0x3F));
    } else {
      return std::nullopt;   // not a code point below U+0100: not written by bytes_as_code_points
    }
  }
  return bytes;
}

// Applies `convert` to every string value in `j` (keys are this file's own ASCII names).
template <typename Convert>
bool convert_strings(json& j, const Convert& convert) {
  if (j.is_string()) {
    auto converted = convert(j.get<std::string>());
    if (!converted) return false;
    j = *converted;
    return true;
  }
  if (j.is_array() || j.is_object())
    for (json& item : j)
      if (!convert_strings(item, convert)) return false;
  return true;
}

}  // namespace

std::string encode_worker_options(const WorkerOptions& o) {
  json j = {{"select", o.select}, {"cell", o.cell}, {"process", o.process}};
  convert_strings(j, [](const std::string& s) { return std::optional(bytes_as_code_points(s)); });
  return j.dump();
}

Result<WorkerOptions> decode_worker_options(std::string_view line) {
  json j = json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail(ErrorStage::worker, "the options line is not a JSON object");
  if (!convert_strings(j, code_points_as_bytes))
    return fail(ErrorStage::worker, "the options line has a string that is not bytes as code points");
  try {
    WorkerOptions o;
    j.at("select").get_to(o.select);
    j.at("cell").get_to(o.cell);
    j.at("process").get_to(o.process);
    return o;
  } catch (const json::exception& e) {
    return fail(ErrorStage::worker, std::string("the options line: ") + e.what());
  }
}

void apply_process_settings(const ProcessSettings& settings) {
  set_cache_settings(settings.caches);
  choose_vulkan_device(settings.vulkan_device);
  choose_gl_platform(settings.gl_platform);
}

}  // namespace shaderbed
