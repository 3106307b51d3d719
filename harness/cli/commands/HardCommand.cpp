// `shaderbed hard [--case A,B | path/to/case.toml] [--backend ..] [--lang ..] [--scenario ..] [--size N] [--json FILE] [--out DIR]`:
// the hard-case suite (docs/hard-cases.md): per model, NaN/Inf counts, max relative
// error and ULPs of the book variants and the robust one on slices and hard geometry; for
// a user's case file, its shader against its own double twin and the line that loses
// significance at the worst pixel.
#include <fstream>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "cli/commands/JsonOutput.h"
#include "compile/IsolatedCompile.h"
#include "hard/HardOutput.h"
#include "hard/HardRunner.h"

namespace shaderbed {

Command add_hard_command(CLI::App& app) {
  auto o = std::make_shared<hard::HardOptions>();
  auto json_path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "hard",
      "Run the hard-case suite: parameter-space slices (one configuration per pixel) and hard geometry, on both "
      "backends against the double reference; per model NaN/Inf counts, max relative error and ULPs of the book "
      "variants (vertex, pixel) and the robust one (pixel_robust). Given a case file of your own (--case "
      "path/to/case.toml), runs its shaders on the same slices against their own double twin and names the line "
      "that loses significance at each row's worst pixel. Exit 1 if a row fails.");
  cmd->add_option("--case", o->cases,
                  "Library cases to run (default: all), or case files of your own (a path ending in .toml)")
      ->delimiter(',');
  cmd->add_option("--backend", o->backends, "vulkan, gl (default: both)")->delimiter(',');
  cmd->add_option("--lang", o->languages, "glsl, hlsl, cg (default: all)")->delimiter(',');
  cmd->add_option("--scenario", o->scenarios, "Scenarios to run (default: all that apply)")->delimiter(',');
  cmd->add_option("--cases-dir", o->cases_dir, "Folder of case files (default: the library's shaders/cases)");
  cmd->add_flag("--all-paths", o->all_paths,
                "Every GL path (native GLSL, SPIR-V, SPIRV-Cross GLSL), not only the first of each backend");
  cmd->add_option("--size", o->size, "Slice and image size in pixels (slices round up to odd)")->capture_default_str();
  cmd->add_option("--json", *json_path, "Write the report as JSON (-: standard output, the table then on stderr)");
  cmd->add_option("--out", o->out_dir, "Write images (render, reference, relative error, value mask) here");
  return {cmd, [o, json_path] {
            isolate_compiles();   // a user's case may crash glslang: an error, not the end of the command
            const JsonOutput json(*json_path);
            o->progress = [](const std::string& step) { fmt::print(stderr, "hard: {}\n", step); };
            // A path to a .toml file is the user's own case; a bare name is the library's.
            std::vector<std::string> names;
            for (const std::string& c : o->cases)
              (c.ends_with(".toml") ? o->user_cases : names).push_back(c);
            o->cases = std::move(names);
            auto report = hard::run_hard_cases(*o);
            if (!report) {
              fmt::print(stderr, "shaderbed: hard: {}\n", report.error().to_string());
              return kExitBadInput;
            }
            fmt::print("{}", hard::console_report(*report));
            std::set<std::string> errors;   // each once: a shader that does not compile errors every row alike
            for (const hard::HardRow& r : report->rows)
              if (r.status == CellStatus::error && errors.insert(r.message).second)
                fmt::print(stderr, "shaderbed: hard: {}\n", r.message);
            if (json.wanted()) {
              if (auto ok = json.write(hard::json_report(*report).dump(2) + "\n", "the hard-case JSON"); !ok) {
                fmt::print(stderr, "shaderbed: hard: {}\n", ok.error().to_string());
                return kExitFail;
              }
            }
            for (const hard::HardRow& r : report->rows)
              if (r.status != CellStatus::pass) return kExitFail;
            return 0;
          }};
}

}  // namespace shaderbed
