#include "bench/Bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "run/Runner.h"

namespace shaderbed::bench {

std::vector<ComparedCell> default_compared_cells() {
  return {{"phong", "pixel", "sphere"}, {"cook_torrance", "pixel", "torus"}};
}

Result<BenchReport> run_bench(const BenchOptions& o) {
  const auto step = [&](const std::string& text) {
    if (o.on_step) o.on_step(text);
  };
  for (const ComparedCell& cell : o.compared)
    if (auto ok = check_compared_cell(cell, o.cases_dir); !ok) return std::unexpected(ok.error());
  ProcessOptions processes{.cell_args = o.cell_args.empty() ? default_cell_args() : o.cell_args,
                           .size = o.size,
                           .runs = o.runs,
                           .on_step = o.on_step};
  for (const std::string& c : o.cases) processes.suite_args.insert(processes.suite_args.end(), {"--case", c});
  processes.suite_args.insert(processes.suite_args.end(), {"--size", std::to_string(o.size), "--jobs", std::to_string(o.jobs)});
  if (!o.cases_dir.empty()) processes.suite_args.insert(processes.suite_args.end(), {"--cases-dir", o.cases_dir});
  if (!o.out_dir.empty()) processes.suite_args.insert(processes.suite_args.end(), {"--out", o.out_dir, "--keep-images", "all"});
  auto measured = measure_processes(processes);
  if (!measured) return std::unexpected(measured.error());

  BenchReport report;
  report.tools = measured->cold.tools;
  report.size = o.size;
  report.jobs = o.jobs;
  report.suite_timing = {.warmup = 0, .runs = 0};
  report.cases = o.cases;
  report.suite = measured->cold.cost;
  report.suite_cpu_ms = measured->cold.cpu_ms;
  report.suite_failures = measured->cold.failures;
  report.processes = std::move(*measured);

  for (const ComparedCell& cell : o.compared) {
    step(fmt::format("reference vs drivers: {}, {} runs each", cell.label(), o.runs));
    auto timed = time_reference_against_drivers(cell, {.cases_dir = o.cases_dir, .size = o.size, .runs = o.runs});
    if (!timed) return std::unexpected(timed.error());
    report.comparisons.push_back(std::move(*timed));
  }
  return report;
}

}  // namespace shaderbed::bench
