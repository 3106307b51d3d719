// `shaderbed stats [--case ..] [--variant ..] [--lang ..] [--json FILE] [--csv FILE]
//  [--baseline OLD.json [--metric M] [--fail-above PCT]] [--from NEW.json]`:
// SPIR-V instruction counts by class per case x variant x language x stage, as compiled
// and after spirv-opt -O / -Os, the SPIRV-Cross GLSL size and the book's DX9 count;
// against a baseline, a shader-db style helped/HURT report.
#include <chrono>
#include <memory>

#include <unistd.h>

#include <fmt/format.h>

#include "backends/Backend.h"
#include "cli/commands/Command.h"
#include "cli/commands/JsonOutput.h"
#include "compile/IsolatedCompile.h"
#include "core/WritablePath.h"
#include "report/ConsoleProgress.h"
#include "run/Runner.h"
#include "stats/Baseline.h"
#include "stats/Collect.h"

namespace shaderbed {
namespace {

struct StatsArguments {
  stats::StatsOptions options;
  std::string json, csv, baseline, from, metric = "spirv_opt";
  double fail_above = -1;
  bool quiet = false, wide = false;
};

}  // namespace

Command add_stats_command(CLI::App& app) {
  auto args = std::make_shared<StatsArguments>();
  CLI::App* cmd = app.add_subcommand(
      "stats",
      "SPIR-V instruction counts by class (arithmetic, GLSL.std.450 calls, texture, control, memory, conversion, "
      "other) for every case x variant x language x stage, as compiled and after spirv-opt -O/-Os, with the "
      "SPIRV-Cross GLSL size and the book's DX9 count; --baseline compares with an earlier --json run");
  cmd->add_option("--case", args->options.cases, "Case names; default: all")->delimiter(',');
  cmd->add_option("--variant", args->options.variants, "Variants (vertex, pixel, pixel_lut, ...); default: all")
      ->delimiter(',');
  cmd->add_option("--lang", args->options.languages, "Languages (glsl, hlsl, cg); default: all")->delimiter(',');
  cmd->add_option("--cases-dir", args->options.cases_dir, "Folder of case files")->default_str(default_cases_dir());
  cmd->add_option("--json", args->json, "Write the counts as JSON (-: standard output, the table then on stderr)");
  cmd->add_option("--csv", args->csv, "Write the counts as CSV");
  cmd->add_option("--from", args->from, "Use this earlier --json file instead of compiling the library");
  cmd->add_option("--baseline", args->baseline, "Compare with this earlier --json file (shader-db style report)");
  cmd->add_option("--metric", args->metric, "Number compared with the baseline: spirv, spirv_opt, spirv_os, glsl_lines")
      ->capture_default_str();
  cmd->add_option("--fail-above", args->fail_above,
                  "With --baseline: exit 1 when the affected shaders' total grows by more than PCT percent");
  cmd->add_flag("--quiet", args->quiet, "Do not print the table");
  cmd->add_flag("--wide", args->wide, "Print every class count, languages side by side (about 230 columns)");
  cmd->add_flag("!--no-nir", args->options.nir,
                "Skip the driver (Mesa NIR) counts, which run one child process per program and backend");

  return {cmd, [args] {
            if (auto ok = stats::check_metric(args->metric); !ok) {
              fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
              return kExitBadInput;
            }
            for (const auto& [path, option] : {std::pair{args->json, "--json"}, std::pair{args->csv, "--csv"}})
              if (!path.empty())
                if (auto ok = check_not_an_input(path, option, {args->from, args->baseline}); !ok) {
                  fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
                  return kExitBadInput;
                }
            if (args->fail_above >= 0 && args->baseline.empty()) {
              fmt::print(stderr, "shaderbed: --fail-above needs --baseline\n");
              return kExitBadInput;
            }
            const JsonOutput json(args->json);
            const auto start = std::chrono::steady_clock::now();
            Result<stats::StatsReport> report = fail(ErrorStage::stats, "nothing");
            if (!args->from.empty()) {
              report = stats::read_stats_json(args->from);
            } else {
              if (args->options.cases_dir.empty()) args->options.cases_dir = default_cases_dir();
              isolate_compiles();   // a shader glslang crashes on is an error row; the others are counted
              // Progress on stderr (the library takes seconds); stdout keeps only the table.
              ConsoleProgress progress(stderr, isatty(STDERR_FILENO), args->quiet);
              args->options.on_step = [&progress](size_t done, size_t total, const std::string& what) {
                progress.update(done, total, "steps", what);
              };
              args->options.gl_platform = chosen_gl_platform().platform;
              args->options.gl_device = chosen_gl_platform().device;
              report = stats::collect_stats(args->options);
            }
            if (!report) {
              fmt::print(stderr, "shaderbed: {}\n", report.error().to_string());
              return kExitBadInput;
            }
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (!args->quiet) fmt::print("{}", stats::format_table(*report, args->wide ? stats::TableForm::wide : stats::TableForm::compact));
            int errors = 0;
            for (const auto& e : report->entries)
              if (!e.error.empty()) {
                ++errors;
                fmt::print(stderr, "shaderbed: stats: {}: {}\n", e.key(), e.error);
              }
            if (args->from.empty())
              fmt::print("{} entries in {:.1f} s{}\n", report->entries.size(), seconds,
                         errors ? fmt::format(", {} with compile errors", errors) : "");
            if (json.wanted())
              if (auto ok = json.write(stats::to_json(*report), "the counts' JSON"); !ok) {
                fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
                return kExitFail;
              }
            if (!args->csv.empty())
              if (auto ok = stats::write_text_file(args->csv, stats::to_csv(*report)); !ok) {
                fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
                return kExitFail;
              }
            int status = errors ? kExitFail : 0;
            if (!args->baseline.empty()) {
              auto old = stats::read_stats_json(args->baseline);
              if (!old) {
                fmt::print(stderr, "shaderbed: {}\n", old.error().to_string());
                return kExitBadInput;
              }
              const stats::Comparison c = stats::compare(*old, *report, args->metric);
              fmt::print("\n{}", stats::format_comparison(c));
              if (args->fail_above >= 0 && stats::exceeds(c, args->fail_above)) {
                fmt::print(stderr, "shaderbed: stats: affected shaders grew {:+.2f}% (> --fail-above {})\n",
                           c.affected_percent(), args->fail_above);
                status = kExitFail;
              }
            }
            return status;
          }};
}

}  // namespace shaderbed
