#include "bench/Bench.h"

#include <sys/resource.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/run/Runner.h"

namespace shaderbed::bench {
namespace {

double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

}  // namespace

std::vector<ComparedCell> default_compared_cells() {
  return {{"phong", "pixel", "sphere"}, {"cook_torrance", "pixel", "torus"}};
}

Result<BenchReport> run_bench(const BenchOptions& o) {
  const auto step = [&](const std::string& text) {
    if (o.on_step) o.on_step(text);
  };
  for (const ComparedCell& cell : o.compared)
    if (auto ok = check_compared_cell(cell, o.cases_dir); !ok) return std::unexpected(ok.error());
  RunOptions run;
  run.cases_dir = o.cases_dir;
  run.cases = o.cases;
  run.size = o.size;
  run.jobs = o.jobs;
  run.out_dir = o.out_dir;
  // Each draw made once, untimed: timed repeats would be time the parts do not show.
  run.timing = {.warmup = 0, .runs = 0};
  if (o.on_cell) run.on_cell = [&](size_t done, size_t total, const CellResult&) { o.on_cell(done, total); };
  step(fmt::format("suite: {} at {}x{}", o.cases.empty() ? "every case" : fmt::format("{}", fmt::join(o.cases, ",")),
                   o.size, o.size));
  const double cpu_before = process_cpu_ms();
  auto suite = run_suite(run);
  const double suite_cpu_ms = process_cpu_ms() - cpu_before;
  if (!suite) return std::unexpected(suite.error());

  BenchReport report;
  report.tools = suite->tools;
  report.size = o.size;
  report.jobs = o.jobs;
  report.suite_timing = run.timing;
  report.cases = o.cases;
  report.suite = suite_cost(*suite);
  report.suite_cpu_ms = suite_cpu_ms;
  report.suite_failures = suite->count("fail");

  for (const ComparedCell& cell : o.compared) {
    step(fmt::format("reference vs drivers: {}, {} runs each", cell.label(), o.runs));
    auto timed = time_reference_against_drivers(cell, {.cases_dir = o.cases_dir, .size = o.size, .runs = o.runs});
    if (!timed) return std::unexpected(timed.error());
    report.comparisons.push_back(std::move(*timed));
  }
  return report;
}

}  // namespace shaderbed::bench
