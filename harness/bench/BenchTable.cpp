#include "bench/BenchTable.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace shaderbed::bench {
namespace {

std::string percent(double part, double whole) { return whole > 0 ? fmt::format("{:.1f} %", 100 * part / whole) : "-"; }

std::string interval_text(const TimingInterval& t) {
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

std::string verdict(bool met) { return met ? "met" : "MISSED"; }

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
    out += fmt::format("    {:<34} {}\n", "reference (CPU, double)", interval_text(c.reference));
    for (const DriverDraw& d : c.draws)
      out += fmt::format("    {:<34} {}   reference / {} = {:.1f}×\n",
                         fmt::format("{}/{} ({})", d.backend, d.path, d.driver), interval_text(d.wall), d.driver,
                         d.reference_ratio);
    if (c.twin_of_lavapipe > 0)
      out += fmt::format("    the shader's double twin on one thread = {:.1f}× lavapipe's draw (goal <= {:.0f}×): {}\n",
                         c.twin_of_lavapipe, twin_draw_goal, verdict(c.twin_of_lavapipe <= twin_draw_goal));
  }
  return out;
}

std::string process_section(const BenchReport& r) {
  const ProcessCosts& p = r.processes;
  using G = ProcessGoals;
  std::string out =
      "Processes: the binary started as a child, wall clock from spawn to exit, caches in private folders\n"
      "(cold: empty; warm: filled by the run before; off: --no-driver-cache --no-compile-cache)\n";
  const double jit_floor = p.cold.cost.workers > 0 ? p.cold.cost.driver_build_ms() / p.cold.cost.workers : 0;
  const auto suite = [&](const SuiteProcess& s, const std::string& note) {
    out += fmt::format("  {:<22} {:9.2f} s   CPU {:7.2f} s   {}\n", "suite, caches " + s.state, s.wall_ms / 1000,
                       s.cpu_ms / 1000, note);
  };
  const double cold_of_jit = jit_floor > 0 ? p.cold.wall_ms / jit_floor : 0;
  suite(p.cold, fmt::format("{:.2f}x the JIT floor (pipeline build {:.2f} s / {} workers; goal <= {}x): {}", cold_of_jit,
                            p.cold.cost.driver_build_ms() / 1000, p.cold.cost.workers, G::cold_suite_of_jit,
                            verdict(cold_of_jit <= G::cold_suite_of_jit)));
  const double warm_of_cold = p.cold.wall_ms > 0 ? p.warm.wall_ms / p.cold.wall_ms : 0;
  const bool default_suite = r.cases.empty() && r.size == 256;
  std::string warm_note = fmt::format("{:.2f}x cold (goal <= {}x): {}", warm_of_cold, G::warm_suite_of_cold,
                                      verdict(warm_of_cold <= G::warm_suite_of_cold));
  if (default_suite)
    warm_note += fmt::format("; goal <= {:.1f} s: {}", G::warm_suite_ms / 1000, verdict(p.warm.wall_ms <= G::warm_suite_ms));
  suite(p.warm, warm_note);
  const double twin_of_warm = p.warm.wall_ms > 0 ? p.twin.wall_ms / p.warm.wall_ms : 0;
  out += fmt::format("  {:<22} {:9.2f} s   CPU {:7.2f} s   {:.2f}x warm (every cell also drawn by its double twin; "
                     "goal <= {}x): {}\n",
                     "suite, warm, --twin", p.twin.wall_ms / 1000, p.twin.cpu_ms / 1000, twin_of_warm,
                     G::twin_suite_of_warm, verdict(twin_of_warm <= G::twin_suite_of_warm));
  suite(p.off, fmt::format("{:.2f}x cold", p.cold.wall_ms > 0 ? p.off.wall_ms / p.cold.wall_ms : 0));
  const auto timed = [&](const ProcessTiming& t, const std::string& note) {
    out += fmt::format("  {:<22} {:9.1f} ms [{:.1f}, {:.1f}]  CPU {:6.1f} ms  {}\n", t.label, t.wall.median, t.wall.low,
                       t.wall.high, t.cpu_ms, note);
  };
  timed(p.cell_cold, fmt::format("goal < {} ms: {}", G::cold_cell_ms, verdict(p.cell_cold.wall.median < G::cold_cell_ms)));
  timed(p.cell_warm, fmt::format("goal <= {} ms: {}", G::warm_cell_ms, verdict(p.cell_warm.wall.median <= G::warm_cell_ms)));
  for (const ProcessTiming& t : p.startup)
    timed(t, t.label == "--help" ? fmt::format("goal <= {} ms: {}", G::help_ms, verdict(t.wall.median <= G::help_ms)) : "");
  out += fmt::format("  one cell: shaderbed {}\n  medians [CI] of {} starts each\n\n", p.cell_warm.command,
                     p.cell_warm.wall_ms.size());
  if (p.failing_cell.size() == 2) {
    const ProcessTiming &run = p.failing_cell[0], &explain = p.failing_cell[1];
    out += "Where a port goes wrong (one failing cell as a process, warm caches)\n";
    timed(run, "its fits and the line where it departs included");
    timed(explain, fmt::format("{:.2f}x run: the cell again, and its worst pixel line by line",
                               run.wall.median > 0 ? explain.wall.median / run.wall.median : 0));
    out += fmt::format("  cell: shaderbed {}\n\n", explain.command);
  }
  return out;
}

}  // namespace

std::string bench_table(const BenchReport& r) {
  std::string out = fmt::format("shaderbed bench: vulkan {} | gl {}\n\n", r.tools.vulkan_driver, r.tools.gl_driver);
  return out + process_section(r) + "Where the cold suite's time went:\n" + suite_section(r) + comparison_section(r);
}

}  // namespace shaderbed::bench
