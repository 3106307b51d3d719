#include "bench/BenchTable.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace shaderbed::bench {
namespace {

std::string percent(double part, double whole) { return whole > 0 ? fmt::format("{:.1f} %", 100 * part / whole) : "-"; }

std::string interval(const TimingInterval& t) {
  return fmt::format("{:9.3f} ms [{:.3f}, {:.3f}] {:.0f}%", t.median, t.low, t.high, 100 * t.level);
}

std::string suite_section(const BenchReport& r) {
  const SuiteCost& s = r.suite;
  std::string out = fmt::format(
      "Suite: {}, {} cells at {}x{}, {} worker{} (--jobs {}), each draw made once, untimed (--warmup {} --repeat {})\n",
      r.cases.empty() ? "every case" : fmt::format("{}", fmt::join(r.cases, ",")), s.cells, r.size, r.size, s.workers,
      s.workers == 1 ? "" : "s", r.jobs, r.suite_timing.warmup, r.suite_timing.runs);
  out += fmt::format("  wall time {:.2f} s; process CPU time {:.2f} s (user + sys, all threads); {} failed, {} could "
                     "not run\n\n",
                     s.wall_ms / 1000, r.suite_cpu_ms / 1000, r.suite_failures, s.errors);
  out += fmt::format("  {:<10} {:<44} {:>11} {:>6} {:>9} {:>12}\n", "where", "what", "ms", "times", "of parts",
                     fmt::format("of wall x {}", s.workers));
  const auto row = [&](const char* where, const std::string& what, double ms, const std::string& times) {
    out += fmt::format("  {:<10} {:<44} {:>11.1f} {:>6} {:>9} {:>12}\n", where, what, ms, times,
                       percent(ms, s.summed_ms), percent(ms, s.worker_ms));
  };
  for (CostOwner owner : {CostOwner::driver, CostOwner::shaderbed}) {
    const bool driver = owner == CostOwner::driver;
    const char* where = driver ? "drivers" : "shaderbed";
    for (const CostPart& p : s.parts)
      if (p.owner == owner) row(where, p.description, p.ms, fmt::format("{}", p.count));
    row(where, driver ? "= the drivers' work" : "= shaderbed's own work", driver ? s.driver_ms : s.shaderbed_ms, "");
  }
  row("", "= summed parts", s.summed_ms, "");
  out += fmt::format("  {:<10} {:<44} {:>11.1f} {:>6} {:>9} {:>12}\n", "", "unaccounted: wall x workers - parts",
                     s.unaccounted_ms, "", "", percent(s.unaccounted_ms, s.worker_ms));
  out += fmt::format(
      "  (driver start-up, case files, meshes, LUTs, attribution, scheduling, idle workers)\n"
      "  drivers : shaderbed = {} : {} of the summed parts. Each part is its worker thread's wall time;\n"
      "  with {} workers they add up to more than the wall time, and they include time the thread waited\n"
      "  for a core (compare the process CPU time above).\n",
      percent(s.driver_ms, s.summed_ms), percent(s.shaderbed_ms, s.summed_ms), s.workers);
  return out;
}

std::string comparison_section(const BenchReport& r) {
  if (r.comparisons.empty()) return "";
  std::string out = fmt::format(
      "\nReference rasteriser vs the drivers' draw: same scene, {}x{}, 1 worker, median [CI] of {} runs after 1 "
      "untimed.\n"
      "Draws: wall time of clear + draw + wait, without the pipeline build, on the drivers' rasteriser threads\n"
      "(LP_NUM_THREADS, default one per core); the reference renders on one thread (docs/timing.md)\n",
      r.size, r.size, r.comparisons.front().runs);
  for (const ReferenceVsDrivers& c : r.comparisons) {
    out += fmt::format("  {} ({} shaders)\n", c.cell.label(), c.draws.empty() ? "no" : c.draws.front().language);
    out += fmt::format("    {:<24} {}\n", "reference (CPU, double)", interval(c.reference));
    for (const DriverDraw& d : c.draws)
      out += fmt::format("    {:<24} {}   reference / {} = {:.1f}×\n",
                         fmt::format("{}/{} ({})", d.backend, d.path, d.driver), interval(d.wall), d.driver,
                         d.reference_ratio);
  }
  return out;
}

}  // namespace

std::string bench_table(const BenchReport& r) {
  std::string out = fmt::format("shaderbed bench: vulkan {} | gl {}\n\n", r.tools.vulkan_driver, r.tools.gl_driver);
  return out + suite_section(r) + comparison_section(r);
}

}  // namespace shaderbed::bench
