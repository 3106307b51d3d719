#include "run/WorkerProtocol.h"

#include <charconv>

#include <nlohmann/json.hpp>

#include "backends/Backend.h"
#include "core/CacheSettings.h"
#include "report/JsonReport.h"

namespace shaderbed {
namespace {

using json = nlohmann::json;

std::vector<std::string> strings(const json& j, const char* key) {
  std::vector<std::string> out;
  if (j.contains(key) && j[key].is_array())
    for (const json& e : j[key])
      if (e.is_string()) out.push_back(e.get<std::string>());
  return out;
}

}  // namespace

std::string worker_options_line(const RunOptions& o) {
  const CacheSettings caches = cache_settings();
  const json j = {{"cases_dir", o.cases_dir},
                  {"cases", o.cases},
                  {"variants", o.variants},
                  {"backends", o.backends},
                  {"languages", o.languages},
                  {"shapes", o.shapes},
                  {"params", o.params},
                  {"size", o.size},
                  {"out_dir", o.out_dir},
                  {"save_images_dir", o.save_images_dir},
                  {"against_dir", o.against_dir},
                  {"shard", o.shard},
                  {"warmup", o.timing.warmup},
                  {"runs", o.timing.runs},
                  {"mesh_slices", o.mesh_slices},
                  {"relaxed_precision", o.relaxed_precision},
                  {"per_pixel_reference", o.per_pixel_reference},
                  {"cache_root", caches.root},
                  {"driver_cache", caches.driver},
                  {"compile_cache", caches.compile},
                  {"vulkan_device", chosen_vulkan_device()}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

Result<RunOptions> apply_worker_options_line(std::string_view line) {
  const json j = json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail("worker", "the options line is not a JSON object");
  RunOptions o;
  o.cases_dir = j.value("cases_dir", std::string());
  o.cases = strings(j, "cases");
  o.variants = strings(j, "variants");
  o.backends = strings(j, "backends");
  o.languages = strings(j, "languages");
  o.shapes = strings(j, "shapes");
  o.params = strings(j, "params");
  o.size = j.value("size", 256);
  o.out_dir = j.value("out_dir", std::string());
  o.save_images_dir = j.value("save_images_dir", std::string());
  o.against_dir = j.value("against_dir", std::string());
  o.shard = j.value("shard", std::string());
  o.timing = {.warmup = j.value("warmup", 1), .runs = j.value("runs", 6)};
  o.mesh_slices = j.value("mesh_slices", 0);
  o.relaxed_precision = j.value("relaxed_precision", false);
  o.per_pixel_reference = j.value("per_pixel_reference", false);
  o.jobs = 1;
  set_cache_settings({.root = j.value("cache_root", std::string()),
                      .driver = j.value("driver_cache", true),
                      .compile = j.value("compile_cache", true)});
  choose_vulkan_device(j.value("vulkan_device", std::string()));
  return o;
}

Result<WorkerEvent> parse_worker_event(std::string_view line) {
  WorkerEvent e;
  const size_t space = line.find(' ');
  const std::string_view word = line.substr(0, space);
  const std::string_view rest = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
  if (word == "hello" || word == "cell") {
    auto report = parse_json(rest, "worker");
    if (!report) return std::unexpected(report.error());
    e.kind = word == "hello" ? WorkerEvent::Kind::hello : WorkerEvent::Kind::cell;
    e.report = std::move(*report);
    if (e.kind == WorkerEvent::Kind::cell && e.report.results.size() != 1)
      return fail("worker", "a cell message holds " + std::to_string(e.report.results.size()) + " results");
  } else if (word == "step") {
    const size_t last = rest.rfind(' ');
    if (last == std::string_view::npos) return fail("worker", "a step message needs a cell and a step");
    e.kind = WorkerEvent::Kind::step;
    e.cell_id = std::string(rest.substr(0, last));
    e.step = std::string(rest.substr(last + 1));
  } else if (word == "done") {
    e.kind = WorkerEvent::Kind::done;
    size_t* counts[] = {&e.compiles.disk_hits, &e.compiles.compiles, &e.compiles.memory_hits};
    std::string_view numbers = rest;
    for (size_t* out : counts) {
      while (numbers.starts_with(' ')) numbers.remove_prefix(1);
      const auto [end, ec] = std::from_chars(numbers.data(), numbers.data() + numbers.size(), *out);
      if (ec != std::errc()) return fail("worker", "a done message needs three counts");
      numbers.remove_prefix(size_t(end - numbers.data()));
    }
  }
  return e;
}

}  // namespace shaderbed
