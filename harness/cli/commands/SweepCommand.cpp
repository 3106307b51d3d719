#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "cli/commands/JsonOutput.h"
#include "compile/IsolatedCompile.h"
#include "run/Runner.h"
#include "report/HtmlReport.h"
#include "sweep/StopSignals.h"
#include "sweep/Sweep.h"
#include "sweep/SweepOutput.h"

namespace shaderbed {
namespace {

struct SweepArguments {
  SweepOptions options;
  std::vector<std::string> axes;
  std::string json, chart, html;
};

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArguments>();
  SweepOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Render one case across a parameter space and place every variant on a speed-against-error chart: "
      "interior RMSE and max error against the reference, draw time (median and CI of timed repeats) and "
      "SPIR-V instruction count per point");
  cmd->add_option("case", o.case_name, "Case name (shaders/cases/NAME.toml)")->required();
  cmd->add_option("--param", args->axes,
                  "An axis NAME=LO:HI:STEPS[:lin|:log] (repeatable; axes multiply). NAME is a scalar case parameter "
                  "(lut_size, power, slope_m, ...) or 'tessellation' (shape slices). Steps are geometric when LO > 0 "
                  "and HI/LO >= 8, else linear. Example: --param lut_size=8:256:6");
  cmd->add_option("--precision", o.precisions,
                  "fp32 and/or relaxed (mediump / min16float: SPIR-V RelaxedPrecision); default fp32")
      ->delimiter(',');
  cmd->add_option("--variant", o.variants, "Variants (default: every variant of the case)")->delimiter(',');
  cmd->add_option("--lang", o.languages, "Languages (default: glsl, else the case's first)")->delimiter(',');
  cmd->add_option("--backend", o.backends, "Backends: vulkan, gl (default: vulkan)")->delimiter(',');
  cmd->add_option("--shape", o.shapes, "Shapes (default: sphere)")->delimiter(',');
  cmd->add_option("--size", o.size, "Image width and height in pixels")->capture_default_str()->check(CLI::Range(8, 4096));
  cmd->add_option("--repeat", o.timing.runs, "Timed draws per point")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--warmup", o.timing.warmup, "Untimed draws before them")->capture_default_str()->check(CLI::Range(0, 100));
  cmd->add_option("--json", args->json, "Write the points as JSON: {\"points\": [{\"params\", \"rmse\", \"max_abs\", "
                                        "\"time_ms\", \"instructions\", ...}]} (-: standard output, the table then on stderr)");
  cmd->add_option("--chart", args->chart,
                  "Write the speed-against-error chart as STEM.png and STEM.svg (gnuplot); one per scene "
                  "(STEM-1, STEM-2, ...) when a case parameter is swept");
  cmd->add_option("--html", args->html, "Write an HTML report of every cell with the chart to this folder");
  cmd->add_option("--cases-dir", o.cases_dir, "Folder of case files")->default_str(default_cases_dir());
  cmd->add_option("--max-points", o.max_points,
                  "Refuse a sweep whose axes (times precisions) make more points than this, before drawing any")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->footer("SIGINT or SIGTERM stops the sweep after the point being drawn and writes --json with the points so "
              "far, marked \"interrupted\" (exit 130 or 143); a second signal ends it at once.");

  return {cmd, [args] {
            SweepOptions options = args->options;
            for (const std::string& text : args->axes) {
              auto axis = parse_sweep_axis(text);
              if (!axis) {
                fmt::print(stderr, "shaderbed: {}\n", axis.error().to_string());
                return kExitBadInput;
              }
              options.axes.push_back(std::move(*axis));
            }
            const bool tty = isatty(STDERR_FILENO);
            options.on_step = [tty](size_t done, size_t total, const std::string& what) {
              if (done == total) {
                if (tty) fmt::print(stderr, "\r{:80}\r", "");
                return;
              }
              if (tty) fmt::print(stderr, "\r[{}/{}] {:<60}", done + 1, total, what);
              else fmt::print(stderr, "[{}/{}] {}\n", done + 1, total, what);
            };
            // The case's shaders compile in a child process: a glslang crash is an error point.
            isolate_compiles();
            const JsonOutput json(args->json);
            const StopSignals signals;
            options.stop_requested = [&signals] { return signals.caught(); };
            auto sweep = run_sweep(options);
            if (!sweep) {
              fmt::print(stderr, "shaderbed: {}\n", sweep.error().to_string());
              return kExitBadInput;
            }
            print_sweep_table(*sweep, stdout);
            std::set<std::string> errors;   // each once: a shader that does not compile errors every point alike
            for (const SweepPoint& p : sweep->points)
              if (p.status == CellStatus::error && errors.insert(p.message).second)
                fmt::print(stderr, "shaderbed: sweep: {}\n", p.message);
            if (!sweep->interrupted_by.empty()) {
              // Only what is quick: the points so far, then the status a shell expects.
              fmt::print(stderr, "shaderbed: sweep: interrupted by {} after {} of {} points{}\n", sweep->interrupted_by,
                         sweep->steps_done, sweep->steps_planned,
                         json.wanted() && !json.on_stdout() ? "; the points so far are in " + args->json : "");
              if (json.wanted())
                if (auto ok = json.write(sweep_json(*sweep, {}), "the sweep's JSON"); !ok)
                  fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
              return signals.exit_status();
            }

            std::string chart_stem = args->chart;
            if (chart_stem.empty() && !args->html.empty())
              chart_stem = (std::filesystem::path(args->html) / "speed_error").string();
            std::vector<SceneChart> charts;
            if (!chart_stem.empty()) {
              auto written = write_sweep_charts(*sweep, chart_stem);
              if (!written) {
                fmt::print(stderr, "shaderbed: {}\n", written.error().to_string());
                return kExitFail;
              }
              charts = std::move(*written);
              for (const SceneChart& c : charts) fmt::print("chart: {} {}\n", c.files.png, c.files.svg);
            }
            if (json.wanted()) {
              if (auto ok = json.write(sweep_json(*sweep, charts), "the sweep's JSON"); !ok) {
                fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
                return kExitFail;
              }
              if (!json.on_stdout()) fmt::print("points: {}\n", args->json);
            }
            if (!args->html.empty()) {
              HtmlOptions html;
              for (const SceneChart& c : charts)
                html.charts.push_back({c.scene.empty() ? sweep->case_name : sweep->case_name + ", " + c.scene,
                                       read_file(c.files.svg),
                                       "draw time against interior RMSE per point; the dashed line is the Pareto front"});
              auto written = write_html(sweep->cells, args->html, html);
              if (!written) {
                fmt::print(stderr, "shaderbed: {}\n", written.error().to_string());
                return kExitFail;
              }
              fmt::print("html: {}\n", written->index_path);
            }
            const bool drawn = std::none_of(sweep->points.begin(), sweep->points.end(),
                                            [](const SweepPoint& p) { return p.status == CellStatus::error; });
            return drawn ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
