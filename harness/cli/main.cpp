// shaderbed: compile a lighting shader, render it on real drivers, diff it against a
// double-precision CPU reference. Exit status: 0 every cell passed, 1 a cell failed or
// could not run, 2 bad input.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/run/Runner.h"
#include "report/ConsoleTable.h"
#include "report/JsonReport.h"

namespace {

constexpr int kExitFail = 1;
constexpr int kExitBadInput = 2;

// "[ 42/140]  12.3 s  ETA 28 s" on one refreshed line, only on a terminal.
class Progress {
 public:
  Progress() : tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}
  void update(size_t done, size_t total) {
    if (!tty_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = done ? elapsed / done * (total - done) : 0;
    fmt::print(stderr, "\r[{:>4}/{}] {:6.1f} s  ETA {:5.1f} s", done, total, elapsed, eta);
    if (done == total) fmt::print(stderr, "\r{:60}\r", "");
  }

 private:
  bool tty_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"shaderbed: a cross-API shader test bench. Compiles HLSL/GLSL lighting shaders to SPIR-V, renders them "
               "on Vulkan (lavapipe) and OpenGL (OSMesa) and compares every image with a double-precision CPU "
               "reference."};
  app.require_subcommand(1);

  shaderbed::RunOptions run;
  std::string json_path;
  CLI::App* run_cmd = app.add_subcommand("run", "Render the suite's cells and compare them with the reference");
  run_cmd->add_option("--case", run.cases, "Case names (shaders/cases/NAME.toml); default: all")->delimiter(',');
  run_cmd->add_option("--variant", run.variants, "Variants: vertex (lighting per vertex), pixel (per pixel); default: all")
      ->delimiter(',');
  run_cmd->add_option("--backend", run.backends, "Backends: vulkan, gl; default: both")->delimiter(',');
  run_cmd->add_option("--lang", run.languages, "Languages: hlsl, glsl; default: every language a case has")->delimiter(',');
  run_cmd->add_option("--shape", run.shapes, "Shapes: sphere, cube, cone, torus; default: all")->delimiter(',');
  run_cmd->add_option("--size", run.size, "Image width and height in pixels")->capture_default_str();
  run_cmd->add_option("--out", run.out_dir, "Folder for renders, references and error images (EXR + PNG)");
  run_cmd->add_option("--json", json_path, "Write the results as JSON to this file");
  run_cmd->add_option("--cases-dir", run.cases_dir, "Folder of case files")->default_str(shaderbed::default_cases_dir());

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  if (run_cmd->parsed()) {
    Progress progress;
    run.on_cell = [&](size_t done, size_t total, const shaderbed::CellResult&) { progress.update(done, total); };
    auto report = shaderbed::run_suite(run);
    if (!report) {
      fmt::print(stderr, "shaderbed: {}\n", report.error().to_string());
      return kExitBadInput;
    }
    shaderbed::print_table(*report, stdout);
    if (!json_path.empty()) {
      if (auto ok = shaderbed::write_json(*report, json_path); !ok) {
        fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
        return kExitFail;
      }
      fmt::print("results: {}\n", std::filesystem::absolute(json_path).string());
    }
    if (!run.out_dir.empty())
      fmt::print("images: {}/<case>/<variant>/<shape>/\n", std::filesystem::absolute(run.out_dir).string());
    return report->count("pass") == report->results.size() && !report->results.empty() ? 0 : kExitFail;
  }
  return 0;
}
