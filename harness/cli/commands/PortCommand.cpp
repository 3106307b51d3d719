#include <unistd.h>

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "author/PortCase.h"
#include "cli/commands/Command.h"
#include "cli/commands/ReportOutputs.h"
#include "compile/IsolatedCompile.h"
#include "core/ThisExecutable.h"
#include "core/WritablePath.h"
#include "report/ConsoleProgress.h"
#include "report/ConsoleReport.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

struct PortArguments {
  std::string file;
  std::string to;
  std::string from;
  std::string out_dir;
  bool force = false;
  RunOptions run;
  ReportOutputs outputs;
  ConsoleOptions console;
};

}  // namespace

Command add_port_command(CLI::App& app) {
  auto args = std::make_shared<PortArguments>();
  CLI::App* cmd = app.add_subcommand(
      "port",
      "Port a case's shaders to another language with SPIRV-Cross, keeping the original's names, write the case "
      "that judges the port against the original's render, and run it");
  cmd->footer(
      "Writes <case stem>.port.<target>/ next to the case (or --out-dir): the ported shaders and <case stem>.port.toml, "
      "whose reference is the original drawn on vulkan/spirv. Prints the files, what SPIRV-Cross changed or could not "
      "keep (combined samplers, semantics, precision, flattened blocks, renamed identifiers), then the run's summary. "
      "Exit status as 'run': 0 every cell of the port renders as the original, 1 a cell does not, 2 bad input.\n");
  cmd->add_option("FILE", args->file, "The original's case file (.toml); for a bare shader, write a case first "
                                      "(shaderbed init SHADER)")
      ->required();
  cmd->add_option("--to", args->to,
                  "Target: glsl (GLSL 450 for Vulkan, named uniform blocks), glsl-gl (GLSL 330 core for desktop GL, "
                  "plain uniforms) or hlsl (HLSL SM5, cbuffers)")
      ->required();
  cmd->add_option("--from", args->from,
                  "The original's language (hlsl, glsl, cg); default: the case's reference language, else its only one");
  cmd->add_option("--out-dir", args->out_dir, "Folder for the port and its case; default: <case stem>.port.<target>/ "
                                              "next to the case file");
  cmd->add_flag("--force", args->force, "Overwrite files a previous port wrote");
  cmd->add_option("--backend", args->run.select.backends, "Backends: vulkan, gl; default: both")->delimiter(',');
  cmd->add_option("--shape", args->run.select.shapes, "Shapes: sphere, cube, cone, torus; default: all")->delimiter(',');
  cmd->add_option("--size", args->run.cell.size, "Image width and height in pixels")->capture_default_str();
  cmd->add_option("--out", args->run.cell.out_dir, "Folder for renders, references and error images (EXR + PNG)");
  args->outputs.add_options(cmd);
  add_console_flags(cmd, args->console);
  cmd->add_option("--jobs,-j", args->run.workers.jobs, "Worker threads; 0 = one per core")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  args->run.cell.timing.runs = 0;   // a port is judged on its images: draw once, untimed

  return {cmd, [args] {
            const auto bad_input = [](const Error& e) {
              fmt::print(stderr, "shaderbed: {}\n", e.to_string());
              return kExitBadInput;
            };
            isolate_compiles();   // plan_port compiles the original and the port: a glslang crash is bad input
            auto target = parse_port_target(args->to);
            if (!target) return bad_input(target.error());
            if (!args->outputs.load_charts() || !args->outputs.check_writable()) return kExitBadInput;
            if (!args->run.cell.out_dir.empty())
              if (auto ok = check_writable_folder(args->run.cell.out_dir, "--out"); !ok) return bad_input(ok.error());
            auto plan = plan_port({.case_path = args->file, .from = args->from, .target = *target, .out_dir = args->out_dir});
            if (!plan) return bad_input(plan.error());
            if (!args->force)
              if (const auto existing = existing_port_files(*plan); !existing.empty()) {
                fmt::print(stderr, "shaderbed: {}: {} file{} of the port exist{} already ({}{}); --force overwrites them\n",
                           plan->out_dir, existing.size(), existing.size() > 1 ? "s" : "",
                           existing.size() > 1 ? "" : "s", std::filesystem::path(existing.front()).filename().string(),
                           existing.size() > 1 ? ", ..." : "");
                return kExitBadInput;
              }
            if (auto ok = write_port(*plan); !ok) return bad_input(ok.error());

            fmt::print("wrote {}/\n", plan->out_dir);
            for (const PortFile& f : plan->files)
              fmt::print("  {}\n", std::filesystem::path(f.path).filename().string());
            fmt::print("SPIRV-Cross changed or could not keep ({}):\n", plan->changes.size());
            for (const PortChange& c : plan->changes) fmt::print("  {:<12} {}\n", c.kind, c.message);
            fmt::print("\n");
            std::fflush(stdout);

            RunOptions options = args->run;
            options.report_files = args->outputs.files();
            options.select.cases_dir = plan->out_dir;
            options.select.cases = plan->case_paths;
            options.workers.worker_binary = this_executable().string();   // isolated, as `run`
            ConsoleProgress progress(stderr, isatty(STDERR_FILENO), args->console.view == ConsoleView::quiet);
            options.on_cell = [&](size_t done, size_t total, const CellResult& cell) { progress.update(done, total, cell); };
            auto report = run_suite(options);
            if (!report) return bad_input(report.error());
            print_console_report(*report, stdout, args->console);
            if (!args->outputs.write(*report)) return kExitFail;
            if (!options.cell.out_dir.empty())
              fmt::print("images: {}/<case>/<variant>/<shape>/\n", std::filesystem::absolute(options.cell.out_dir).string());
            return report->acceptable() ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
