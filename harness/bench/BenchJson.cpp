#include "bench/BenchJson.h"

#include <nlohmann/json.hpp>

#include "report/JsonValues.h"

namespace shaderbed::bench {
namespace {

nlohmann::json interval_json(const TimingInterval& t) {
  return {{"median", t.median}, {"low", t.low}, {"high", t.high}, {"level", t.level}};
}

nlohmann::json suite(const SuiteCost& s) {
  nlohmann::json parts = nlohmann::json::object();
  for (const CostPart& p : s.parts)
    parts[p.name] = {{"owner", p.owner == CostOwner::driver ? "driver" : "shaderbed"},
                     {"description", p.description},
                     {"ms", p.ms},
                     {"count", p.count}};
  return {{"cells", s.cells},
          {"errors", s.errors},
          {"wall_ms", s.wall_ms},
          {"workers", s.workers},
          {"worker_ms", s.worker_ms},
          {"parts", parts},
          {"driver_ms", s.driver_ms},
          {"shaderbed_ms", s.shaderbed_ms},
          {"summed_ms", s.summed_ms},
          {"unaccounted_ms", s.unaccounted_ms},
          {"shares", {{"driver", s.driver_share()}, {"shaderbed", s.shaderbed_share()}}}};
}

nlohmann::json comparison(const ReferenceVsDrivers& c) {
  nlohmann::json draws = nlohmann::json::array();
  for (const DriverDraw& d : c.draws)
    draws.push_back({{"backend", d.backend},
                     {"path", d.path},
                     {"language", d.language},
                     {"driver", d.driver},
                     {"wall_ms", interval_json(d.wall)},
                     {"reference_ratio", d.reference_ratio}});
  return {{"case", c.cell.case_name}, {"variant", c.cell.variant}, {"shape", c.cell.shape}, {"size", c.size},
          {"runs", c.runs},           {"reference_ms", interval_json(c.reference)},  {"draws", draws},
          {"twin_of_lavapipe", c.twin_of_lavapipe}};
}

nlohmann::json process(const ProcessTiming& t) {
  return {{"label", t.label},
          {"command", t.command},
          {"wall_ms", {{"median", t.wall.median}, {"low", t.wall.low}, {"high", t.wall.high}, {"level", t.wall.level}}},
          {"runs", t.wall_ms},
          {"cpu_ms", t.cpu_ms}};
}

nlohmann::json suite_process_json(const SuiteProcess& s) {
  return {{"wall_ms", s.wall_ms}, {"cpu_ms", s.cpu_ms}, {"cells", s.cost.cells}, {"build_ms", s.cost.driver_build_ms()},
          {"failures", s.failures}};
}

nlohmann::json processes(const ProcessCosts& p) {
  nlohmann::json startup = nlohmann::json::object();
  for (const ProcessTiming& t : p.startup) startup[t.label] = process(t);
  const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  const double jit_floor = p.cold.cost.workers > 0 ? p.cold.cost.driver_build_ms() / p.cold.cost.workers : 0;
  return {{"suite", {{"cold", suite_process_json(p.cold)}, {"warm", suite_process_json(p.warm)}, {"off", suite_process_json(p.off)},
                     {"twin", suite_process_json(p.twin)}}},
          {"ratios",
           {{"warm_of_cold", ratio(p.warm.wall_ms, p.cold.wall_ms)},
            {"off_of_cold", ratio(p.off.wall_ms, p.cold.wall_ms)},
            {"twin_of_warm", ratio(p.twin.wall_ms, p.warm.wall_ms)},
            {"cold_of_jit_floor", ratio(p.cold.wall_ms, jit_floor)}}},
          {"cell", {{"cold", process(p.cell_cold)}, {"warm", process(p.cell_warm)}}},
          {"startup", startup},
          {"failing_cell", p.failing_cell.size() == 2
                               ? nlohmann::json{{"run", process(p.failing_cell[0])}, {"explain", process(p.failing_cell[1])}}
                               : nlohmann::json(nullptr)}};
}

}  // namespace

std::string bench_json(const BenchReport& r) {
  nlohmann::json comparisons = nlohmann::json::array();
  for (const ReferenceVsDrivers& c : r.comparisons) comparisons.push_back(comparison(c));
  const nlohmann::json j = {
      {"schema", kBenchSchemaVersion},
      {"tools", nlohmann::json(json_tools(r.tools))},
      {"size", r.size},
      {"jobs", r.jobs},
      {"cases", r.cases},
      {"suite", suite(r.suite)},
      {"suite_cpu_ms", r.suite_cpu_ms},
      {"suite_timing", {{"warmup", r.suite_timing.warmup}, {"runs", r.suite_timing.runs}}},
      {"suite_failures", r.suite_failures},
      {"processes", processes(r.processes)},
      {"reference_vs_drivers", comparisons}};
  return j.dump(2) + "\n";
}

}  // namespace shaderbed::bench
