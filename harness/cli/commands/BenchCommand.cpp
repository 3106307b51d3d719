// `shaderbed bench [--case A,B] [--size N] [--jobs N] [--compare case/variant/shape] [--repeat N] [--quick]
// [--json FILE]`: the speed of shaderbed itself (docs/timing.md, "shaderbed bench"). The
// whole suite as a process with caches cold, warm and off, one cell per process, start-up,
// the drivers' share of the cold suite against shaderbed's own, and the CPU reference's
// time against lavapipe's and llvmpipe's draw of the same scene, in one run.
#include <unistd.h>

#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "bench/Bench.h"
#include "bench/BenchJson.h"
#include "bench/BenchTable.h"
#include "cli/commands/Command.h"
#include "run/Runner.h"
#include "core/AtomicFile.h"

namespace shaderbed {
namespace {

struct BenchArguments {
  bench::BenchOptions options;
  std::vector<std::string> compared;   // case/variant/shape
  std::string json;
  bool quick = false;
};

// The ctest's bench: one case at 64x64 and one compared cell, 3 runs. What was given
// explicitly stays.
void apply_quick(BenchArguments& a, const CLI::App& cmd) {
  if (cmd.count("--case") == 0) a.options.cases = {"phong"};
  if (cmd.count("--size") == 0) a.options.size = 64;
  if (cmd.count("--compare") == 0) a.compared = {"phong/pixel/sphere"};
  if (cmd.count("--repeat") == 0) a.options.runs = 3;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArguments>();
  bench::BenchOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Time shaderbed itself, side by side in one run: the whole suite as its own process with caches cold, warm "
      "and off; one cell per process, cold and warm; the start-up of --help, eval and merge; the drivers' share of "
      "the cold suite (build, draw, readback) against shaderbed's own (compile, reference, compare); and the CPU "
      "reference against lavapipe's and llvmpipe's draw of the same scene and size. Each figure is printed beside "
      "its goal (docs/timing.md)");
  cmd->add_option("--case", o.cases, "The suite's cases; default: all (the default suite)")->delimiter(',');
  cmd->add_option("--size", o.size, "Image width and height in pixels (the suite's default)")->capture_default_str();
  cmd->add_option("--jobs,-j", o.jobs, "Workers for the suite; 0 = one per core, as 'run'")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  cmd->add_option("--compare", args->compared,
                  "Cells (case/variant/shape) whose reference render is timed against the drivers' draw; default: "
                  "phong/pixel/sphere, cook_torrance/pixel/torus")
      ->delimiter(',');
  cmd->add_option("--repeat", o.runs,
                  "Timed repeats of each compared render and draw, and starts of each timed process (one cell, "
                  "--help, eval, merge)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--out", o.out_dir,
                  "Write the suite's images here, as 'run --out' does, so image I/O is one of the parts "
                  "(default: none written)");
  cmd->add_option("--cases-dir", o.cases_dir, "Folder of case files")->default_str(default_cases_dir());
  cmd->add_option("--json", args->json, "Write the numbers as JSON");
  cmd->add_flag("--quick", args->quick,
                "A small run for tests: phong only at 64x64, one compared cell, 3 repeats and process starts "
                "(explicit options win)");

  return {cmd, [args, cmd] {
            BenchArguments a = *args;
            if (a.quick) apply_quick(a, *cmd);
            a.options.compared.clear();
            for (const std::string& text : a.compared) {
              auto cell = bench::parse_compared_cell(text);
              if (!cell) {
                fmt::print(stderr, "shaderbed: bench: {}\n", cell.error().to_string());
                return kExitBadInput;
              }
              a.options.compared.push_back(*cell);
            }
            if (a.compared.empty()) a.options.compared = bench::default_compared_cells();
            const bool tty = isatty(STDERR_FILENO);
            a.options.on_step = [](const std::string& step) { fmt::print(stderr, "bench: {}\n", step); };
            a.options.on_cell = [tty](size_t done, size_t total) {
              if (tty) fmt::print(stderr, "\r[{:>4}/{}]{}", done, total, done == total ? "\n" : "");
            };
            auto report = bench::run_bench(a.options);
            if (!report) {
              fmt::print(stderr, "shaderbed: bench: {}\n", report.error().to_string());
              // A compared cell that could not be drawn is a failure, not bad input.
              return report.error().stage == ErrorStage::bench ? kExitFail : kExitBadInput;
            }
            fmt::print("{}", bench::bench_table(*report));
            if (!a.json.empty()) {
              if (auto ok = write_file_atomically(a.json, bench::bench_json(*report), "the bench JSON"); !ok) {
                fmt::print(stderr, "shaderbed: bench: {}\n", ok.error().to_string());
                return kExitFail;
              }
            }
            // A cell that could not run leaves its parts out of the accounting.
            return report->suite.errors == 0 ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
