#include "bench/ProcessCost.h"

#include "run/Runner.h"

#include <unistd.h>   // environ (glibc declares it with _GNU_SOURCE, which g++ and clang++ set)

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "backends/Backend.h"
#include "core/ThisExecutable.h"
#include "core/ChildProcess.h"
#include "core/ScratchDirectory.h"
#include "report/JsonReport.h"

namespace shaderbed::bench {
namespace fs = std::filesystem;
namespace {

std::string self_binary() {
  const fs::path self = this_executable();
  return self.empty() ? std::string("shaderbed") : self.string();
}

// Ours, with the cache folder replaced (SHADERBED_CACHE_DIR and Mesa's own variables, so
// a user's MESA_SHADER_CACHE_DIR cannot make a cold run warm).
std::vector<std::string> child_environment(const fs::path& cache_dir) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    if (entry.starts_with("SHADERBED_CACHE_DIR=") || entry.starts_with("MESA_SHADER_CACHE_DIR=") ||
        entry.starts_with("MESA_SHADER_CACHE_DISABLE=") || entry.starts_with("MESA_GLSL_CACHE_"))
      continue;
    env.push_back(entry);
  }
  env.push_back("SHADERBED_CACHE_DIR=" + cache_dir.string());
  return env;
}

struct Timed {
  double wall_ms = 0;
  ChildExit exit;
};

Result<Timed> run_timed(const std::vector<std::string>& args, const fs::path& cache_dir, const fs::path& capture) {
  std::vector<std::string> argv = {self_binary()};
  // The GL platform this bench was given, so the commands timed start the GL it would use.
  if (const GlPlatformChoice& gl = chosen_gl_platform(); gl != GlPlatformChoice{}) {
    argv.insert(argv.end(), {"--gl-platform", gl.platform});
    if (!gl.device.empty()) argv.insert(argv.end(), {"--gl-device", gl.device});
  }
  argv.insert(argv.end(), args.begin(), args.end());
  const auto t0 = std::chrono::steady_clock::now();
  auto exit = run_child(argv, capture, ErrorStage::bench, child_environment(cache_dir));
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!exit) return std::unexpected(exit.error());
  // run exits 1 when a cell fails: still a measurement. 2 (bad input) or a signal is not.
  if (exit->signal != 0 || exit->code > 1)
    return fail(ErrorStage::bench, fmt::format("'shaderbed {}' ended with {}: {}", fmt::join(args, " "), exit->how(),
                                     exit->stderr_text.substr(0, exit->stderr_text.find('\n'))));
  return Timed{ms, std::move(*exit)};
}

Result<SuiteProcess> suite_process(const std::string& state, std::vector<std::string> args, const fs::path& cache_dir,
                                   const fs::path& scratch) {
  const fs::path json = scratch / ("suite-" + state + ".json");
  args.insert(args.begin(), "run");
  for (const char* a : {"--repeat", "0", "--quiet", "--json"}) args.push_back(a);
  args.push_back(json.string());
  if (state == "off") args.insert(args.begin(), {"--no-driver-cache", "--no-compile-cache"});
  if (state == "twin")
    for (const char* a : {"--twin", "double"}) args.push_back(a);
  auto timed = run_timed(args, cache_dir, scratch);
  if (!timed) return std::unexpected(timed.error());
  auto report = read_json(json.string());
  if (!report) return std::unexpected(report.error());
  return SuiteProcess{state, timed->wall_ms, timed->exit.cpu_ms, suite_cost(*report), report->tools, report->count(CellStatus::fail)};
}

// `runs` starts of one command; `fresh_cache` gives each its own empty cache folder.
Result<ProcessTiming> time_command(const std::string& label, const std::vector<std::string>& args, int runs,
                                   const fs::path& scratch, const std::string& cache_name, bool fresh_cache) {
  ProcessTiming t{label, fmt::format("{}", fmt::join(args, " ")), {}, 0, {}};
  std::vector<double> cpu;
  for (int i = 0; i < runs; ++i) {
    const fs::path cache = scratch / (fresh_cache ? fmt::format("{}-{}", cache_name, i) : cache_name);
    auto timed = run_timed(args, cache, scratch);
    if (!timed) return std::unexpected(timed.error());
    t.wall_ms.push_back(timed->wall_ms);
    cpu.push_back(timed->exit.cpu_ms);
    if (fresh_cache) fs::remove_all(cache);
  }
  t.wall = median_interval(t.wall_ms);
  t.cpu_ms = median_interval(cpu).median;
  return t;
}

}  // namespace

std::vector<std::string> default_cell_args() {
  return {"run", "--case", "phong", "--variant", "pixel", "--lang", "glsl", "--backend", "vulkan",
          "--shape", "sphere", "--repeat", "0", "--quiet"};
}

std::optional<std::pair<std::vector<std::string>, std::vector<std::string>>> failing_cell_commands(int size) {
  const fs::path c = fs::path(default_cases_dir()).parent_path().parent_path() / "tests/differential/cases/tinted_diffuse.toml";
  if (!fs::exists(c)) return std::nullopt;
  const std::string n = std::to_string(size);
  return std::pair{std::vector<std::string>{"run", "--case", c.string(), "--variant", "light_negated", "--lang", "glsl",
                                            "--backend", "vulkan", "--shape", "sphere", "--size", n, "--repeat", "0", "--quiet"},
                   std::vector<std::string>{"explain", c.string(), "--cell", "light_negated/glsl/vulkan/spirv/sphere",
                                            "--size", n}};
}

Result<ProcessCosts> measure_processes(const ProcessOptions& o) {
  const auto step = [&](const std::string& text) {
    if (o.on_step) o.on_step(text);
  };
  auto scratch = ScratchDirectory::create("bench");
  if (!scratch) return std::unexpected(scratch.error());
  const fs::path dir = scratch->path();
  ProcessCosts costs;

  // Cold fills the folder warm reads; off turns both caches off.
  // The twin's run reads the warm caches, so it differs from the warm run by the twins alone.
  for (auto [state, out] : {std::pair{"cold", &costs.cold}, {"warm", &costs.warm}, {"twin", &costs.twin}, {"off", &costs.off}}) {
    step(fmt::format("suite as a process, caches {}", state));
    auto suite = suite_process(state, o.suite_args, dir / (std::string(state) == "off" ? "cache-off" : "cache-suite"), dir);
    if (!suite) return std::unexpected(suite.error());
    *out = std::move(*suite);
  }

  step(fmt::format("one cell as a process, cold and warm, {} runs each", o.runs));
  auto cold = time_command("one cell, cold caches", o.cell_args, o.runs, dir, "cache-cell-cold", true);
  if (!cold) return std::unexpected(cold.error());
  costs.cell_cold = std::move(*cold);
  if (auto fill = run_timed(o.cell_args, dir / "cache-cell-warm", dir); !fill) return std::unexpected(fill.error());
  auto warm = time_command("one cell, warm caches", o.cell_args, o.runs, dir, "cache-cell-warm", false);
  if (!warm) return std::unexpected(warm.error());
  costs.cell_warm = std::move(*warm);

  // merge reads the cold suite's results: a command that draws nothing but parses JSON.
  step(fmt::format("start-up of commands that draw nothing, {} runs each", o.runs));
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"--help", {"--help"}},
      {"eval", {"eval", "phong", "--L", "0,1,0", "--V", "1,1,0"}},
      {"merge", {"merge", (dir / "suite-cold.json").string()}},
  };
  for (const auto& [label, args] : commands) {
    auto t = time_command(label, args, o.runs, dir, "cache-startup", false);
    if (!t) return std::unexpected(t.error());
    costs.startup.push_back(std::move(*t));
  }

  if (auto failing = failing_cell_commands(o.size)) {
    step(fmt::format("a failing port's cell, run and explained, {} runs each", o.runs));
    for (const auto& [label, args] : {std::pair{"run, failing cell", failing->first}, {"explain, same cell", failing->second}}) {
      auto t = time_command(label, args, o.runs, dir, "cache-startup", false);
      if (!t) return std::unexpected(t.error());
      costs.failing_cell.push_back(std::move(*t));
    }
  }
  return costs;
}

}  // namespace shaderbed::bench
