#include "run/WorkerOptions.h"

#include <nlohmann/json.hpp>

namespace shaderbed {

using json = nlohmann::json;

// Field by field, so a renamed member is a compile error here rather than a silent default.
void to_json(json& j, const SuiteSelection& s) {
  j = {{"cases_dir", s.cases_dir}, {"cases", s.cases},         {"variants", s.variants},
       {"backends", s.backends},   {"languages", s.languages}, {"shapes", s.shapes},
       {"params", s.params},       {"shard", s.shard}};
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
       {"twin", c.twin}};
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
  j.at("unused_binding_warnings").get_to(c.unused_binding_warnings);
  j.at("twin").get_to(c.twin);
}

void to_json(json& j, const ProcessSettings& p) {
  j = {{"cache_root", p.caches.root},
       {"driver_cache", p.caches.driver},
       {"compile_cache", p.caches.compile},
       {"vulkan_device", p.vulkan_device}};
}
void from_json(const json& j, ProcessSettings& p) {
  j.at("cache_root").get_to(p.caches.root);
  j.at("driver_cache").get_to(p.caches.driver);
  j.at("compile_cache").get_to(p.caches.compile);
  j.at("vulkan_device").get_to(p.vulkan_device);
}

WorkerOptions worker_options(const RunOptions& o) {
  // Decided here, before any worker starts, so a full cache folder's note is printed once.
  cache_root_writable();
  return {o.select, cell_settings(o), {cache_settings(), chosen_vulkan_device()}};
}

std::string encode_worker_options(const WorkerOptions& o) {
  const json j = {{"select", o.select}, {"cell", o.cell}, {"process", o.process}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

Result<WorkerOptions> decode_worker_options(std::string_view line) {
  const json j = json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail(ErrorStage::worker, "the options line is not a JSON object");
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
}

}  // namespace shaderbed
