#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "cli/commands/ColourChoice.h"
#include "cli/commands/Command.h"
#include "cli/commands/ReportOutputs.h"
#include "core/SignalsHeld.h"
#include "core/ThisExecutable.h"
#include "core/WritablePath.h"
#include "run/Runner.h"
#include "run/StoredImages.h"
#include "report/ConsoleProgress.h"
#include "report/ConsoleReport.h"
#include "report/JsonReport.h"

namespace shaderbed {
namespace {

struct RunArguments {
  RunOptions options;
  bool in_process = false;
  ReportOutputs outputs;
  ConsoleOptions console;
};

}  // namespace

Command add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArguments>();
  RunOptions& run = args->options;
  CLI::App* cmd = app.add_subcommand("run", "Render the suite's cells and compare them with the reference");
  cmd->add_option("--case", run.select.cases,
                  "Case names (NAME.toml in --cases-dir) or case files (any path ending in .toml, e.g. a case "
                  "written next to your own shader); default: every case in --cases-dir")
      ->delimiter(',');
  cmd->add_option("--variant", run.select.variants, "Variants: vertex, pixel, pixel_lut; default: all")->delimiter(',');
  cmd->add_option("--backend", run.select.backends, "Backends: vulkan, gl; default: both")->delimiter(',');
  cmd->add_option("--path", run.select.paths,
                  "Shader paths: spirv (glslang's SPIR-V), glsl (the GLSL source, GL only), cross (SPIRV-Cross's "
                  "GLSL, GL only); default: every path a backend has")
      ->delimiter(',');
  cmd->add_option("--lang", run.select.languages, "Languages: hlsl, glsl, cg; default: every language a case has")
      ->delimiter(',');
  cmd->add_option("--shape", run.select.shapes, "Shapes: sphere, cube, cone, torus; default: all")->delimiter(',');
  cmd->add_option("--param", run.select.params,
                  "Override a case parameter: name=value or name=v1,v2,v3 (repeatable), e.g. --param power=20");
  cmd->add_option("--size", run.cell.size, "Image width and height in pixels")->capture_default_str();
  cmd->add_option("--twin", run.cell.twin,
                  "Also draw every cell's shader with its twin (the SPIR-V executed on the CPU) in this precision "
                  "and report the render against it: double (the exact shader: the render's own fp32 and driver "
                  "error), float (an ideal fp32 device) or half (RelaxedPrecision in 16 bits, as mobile GPUs do)")
      ->check(CLI::IsMember({"double", "float", "half"}));
  cmd->add_option("--out", run.cell.out_dir,
                  "Folder for renders, references and error images (EXR + PNG); default with --html: its folder");
  cmd->add_option("--keep-images", run.cell.keep_images,
                  "Which cells' images --out keeps: failing (every cell that did not pass, with its reference), "
                  "all, or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"failing", "all", "none"}));
  cmd->add_option("--save-images", run.cell.save_images_dir,
                  "Keep every drawn cell's render, exact (EXR: RGBA + coverage), with DIR/manifest.json (case, "
                  "variant, language, backend, path, shape, size, scene, toolchain, SPIR-V hashes), for later runs "
                  "to be judged against with --against");
  cmd->add_option("--against", run.cell.against_dir,
                  "Judge every cell against its own image stored in DIR by an earlier --save-images run (today's "
                  "port against yesterday's known-good run, lavapipe against real hardware) instead of its model "
                  "or original; a different image size is refused, a different toolchain is reported");
  args->outputs.add_options(cmd);
  cmd->add_option("--shard", run.select.shard,
                  "Run shard I of N (e.g. 2/4): case x variant x shape groups are dealt round-robin, so shards "
                  "merged with 'shaderbed merge' equal one whole run");
  cmd->add_option("--expectations", run.expectations,
                  "TOML file of known failures ([[known]] cells = \"case/variant/lang/backend/path/shape\", "
                  "reason = \"...\"; * matches anything): they are reported as known and do not fail the run");
  cmd->add_option("--cases-dir", run.select.cases_dir, "Folder of case files")->default_str(default_cases_dir());
  add_console_flags(cmd, args->console);
  cmd->add_option("--repeat", run.cell.timing.runs,
                  "Timed repeats of every draw (after --warmup untimed ones); 0 = draw once, untimed")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--warmup", run.cell.timing.warmup, "Untimed repeats before the timed ones")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  cmd->add_flag("--no-isolation", args->in_process,
                 "Compile and draw in this process instead of supervised worker processes (faster to debug; a "
                 "compiler crash or a runaway draw then ends the run)");
  cmd->add_option("--draw-timeout", run.workers.draw_timeout_s,
                  "Seconds one cell's draw may take (pipeline build, warm-up and timed repeats) before its worker is "
                  "killed: the cell is 'error: timeout' and a fresh worker goes on")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_option("--compile-timeout", run.workers.compile_timeout_s,
                  "Seconds compiling one program's shaders may take before its worker is killed (its cells are "
                  "errors)")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 86400.0));
  cmd->add_option("--step-timeout", run.workers.step_timeout_s,
                  "Seconds any other step of a worker may take (start-up, the reference, judging, writing images, "
                  "twin, divergence) before it is killed: the cell is 'error: timeout in <step>'; 0 = by the image "
                  "size (60 s up to 512 px, growing with the pixels: 16 min at 2048)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 86400.0));
  cmd->add_option("--worker-memory", run.workers.worker_memory_mb,
                  "MiB of address space each worker may use; an allocation past it ends the worker and its cell is "
                  "'error: out of memory'")
      ->capture_default_str()
      ->check(CLI::Range(size_t(64), size_t(1) << 30));
  cmd->add_option("--jobs,-j", run.workers.jobs,
                  "Worker threads, each with its own Vulkan device and GL context; 0 = one per core. Timings are "
                  "steadiest with --jobs 1")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));

  return {cmd, [args] {
            if (!args->outputs.load_charts() || !args->outputs.check_writable()) return kExitBadInput;
            // An HTML report shows the images: without --out they go beside index.html.
            if (args->options.cell.out_dir.empty()) args->options.cell.out_dir = args->outputs.html;
            // Checked before --out and --save-images are made: neither may be made inside the
            // stored images that judge the run (a case's own are checked once it is read).
            const CellSettings& cell = args->options.cell;
            if (auto ok = check_stored_folders(cell.out_dir, cell.save_images_dir,
                                               stored_reference_dirs(cell.against_dir, {}));
                !ok) {
              fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
              return kExitBadInput;
            }
            for (const auto& [folder, option] : {std::pair{args->options.cell.out_dir, "--out"},
                                                  std::pair{args->options.cell.save_images_dir, "--save-images"}})
              if (!folder.empty())
                if (auto ok = check_writable_folder(folder, option); !ok) {
                  fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
                  return kExitBadInput;
                }
            ConsoleProgress progress(stderr, isatty(STDERR_FILENO), args->console.view == ConsoleView::quiet);
            RunOptions options = args->options;
            options.report_files = args->outputs.files();
            if (!args->in_process) options.workers.worker_binary = this_executable().string();
            options.on_cell = [&](size_t done, size_t total, const CellResult& cell) {
              progress.update(done, total, cell);
            };
            auto report = run_suite(options);
            if (!report) {
              fmt::print(stderr, "shaderbed: {}\n", report.error().to_string());
              return kExitBadInput;
            }
            // A signal now waits until the reports are written: the run is over, and a stop
            // between them would keep some and lose others.
            const SignalsHeld held;
            ConsoleOptions console = args->console;
            std::FILE* const says = args->outputs.console();   // stderr with --json -
            console.colour = colour_on(says);
            print_console_report(*report, says, console);
            if (!args->outputs.write(*report)) return kExitFail;
            if (!options.cell.out_dir.empty())
              fmt::print(says, "images: {}/<case>/<variant>/<shape>/\n", std::filesystem::absolute(options.cell.out_dir).string());
            if (!options.cell.save_images_dir.empty() && report->interruption)
              fmt::print(says, "stored images: none saved (the run was interrupted; {} is as it was)\n",
                         options.cell.save_images_dir);
            else if (!report->stored_images_lost.empty())
              fmt::print(stderr, "shaderbed: stored images: none saved ({}); {} is as it was\n",
                         report->stored_images_lost, options.cell.save_images_dir);
            else if (!options.cell.save_images_dir.empty())
              fmt::print(says, "stored images: {} (judge later runs with --against {})\n",
                         (std::filesystem::absolute(options.cell.save_images_dir) / "manifest.json").string(),
                         options.cell.save_images_dir);
            // Interrupted: the cells it had are written above, marked incomplete.
            if (report->interruption) return 128 + report->interruption->signal;
            if (!report->stored_images_lost.empty()) return kExitFail;
            // A uniform the case leaves unbound is the case's mistake, found before its cells
            // were drawn: bad input, like a missing shader file.
            const size_t unbound = std::ranges::count_if(report->results, [](const CellResult& r) {
              return r.status == CellStatus::error && r.error_stage == "bind";
            });
            if (unbound) {
              fmt::print(stderr, "shaderbed: {} cell{} could not be bound: the case leaves a uniform without a binding "
                                 "(listed above)\n", unbound, unbound == 1 ? "" : "s");
              return kExitBadInput;
            }
            return report->acceptable() ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
