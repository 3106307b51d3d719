#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands/Command.h"
#include "core/AtomicFile.h"
#include "run/ExplainCell.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

struct ExplainArguments {
  std::string case_name;
  std::string cell;
  std::string pixel;
  std::string json;
  RunOptions run;
};

std::optional<twin::PixelAt> parse_pixel(const std::string& text) {
  int x = 0, y = 0;
  char end = 0;
  if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &end) != 2 || x < 0 || y < 0) return std::nullopt;
  return twin::PixelAt{x, y};
}

// The run's own for a failing cell, else the explanation's (a passing cell's too).
const std::optional<CellResult::Divergence>& divergence_of(const ExplainedCell& e) {
  return e.cell.divergence ? e.cell.divergence : e.pixel.divergence;
}

nlohmann::ordered_json explanation_json(const ExplainedCell& e) {
  using json = nlohmann::ordered_json;
  json lines = json::array();
  for (const twin::ListedLine& l : e.pixel.lines) {
    json values = json::array();
    for (const twin::ListedValue& v : l.values)
      values.push_back({{"name", v.name}, {"values", v.values}, {"matches", v.matches}, {"departs", v.departs}});
    lines.push_back({{"file", l.file}, {"line", l.line}, {"source", l.text}, {"values", std::move(values)}});
  }
  json out = {{"cell", e.cell.id()},
              {"status", to_string(e.cell.status)},
              {"max_abs", e.cell.metrics.max_abs},
              {"pixel", {e.pixel.x, e.pixel.y}},
              {"against", e.pixel.against},
              {"lines", std::move(lines)}};
  if (const auto& d = divergence_of(e)) out["divergence"] = {{"kind", d->kind}, {"file", d->file}, {"line", d->line},
                                                              {"text", d->kind == "error" ? d->error : d->text}};
  return out;
}

}  // namespace

Command add_explain_command(CLI::App& app) {
  auto args = std::make_shared<ExplainArguments>();
  CLI::App* cmd = app.add_subcommand(
      "explain", "Show one pixel of a cell's shader line by line, executed by its twin, beside the original's values");
  cmd->footer(
      "Draws and judges the cell as 'run' does, then executes its shader for one pixel on the CPU (the shader's "
      "double twin) and prints every source line it ran there with the values computed on it. For a port judged "
      "against its original, each value says which of the original's it matches, or that it matches nothing; "
      "against a library model, which of the model's quantities (N·L, D, F, ...). A failing cell's divergence (the "
      "line where it departs) comes first. Exit status: 0 explained, 2 bad input or nothing to explain.\n"
      "Example: shaderbed explain tests/differential/cases/tinted_diffuse.toml --cell light_negated/glsl/vulkan/spirv/sphere "
      "--pixel 120,90\n");
  cmd->add_option("CASE", args->case_name, "Case name (in --cases-dir) or case file (.toml)")->required();
  cmd->add_option("--cell", args->cell,
                  "The cell: variant/language/backend/path/shape, as the failure list and the JSON name it (the case "
                  "first is accepted too)")
      ->required();
  cmd->add_option("--pixel", args->pixel, "The pixel X,Y (row 0 at the top); default: where the cell is furthest from "
                                          "its reference");
  cmd->add_option("--json", args->json, "Write the explanation as JSON to this file ('-': standard output)");
  cmd->add_option("--size", args->run.cell.size, "Image width and height in pixels")->capture_default_str();
  cmd->add_option("--cases-dir", args->run.select.cases_dir, "Folder of case files; default: the library's");
  cmd->add_option("--param", args->run.select.params, "Override a case parameter: name=value or name=v1,v2,v3");

  return {cmd, [args] {
            const auto bad_input = [](const std::string& message) {
              fmt::print(stderr, "shaderbed: explain: {}\n", message);
              return kExitBadInput;
            };
            std::optional<twin::PixelAt> pixel;
            if (!args->pixel.empty() && !(pixel = parse_pixel(args->pixel)))
              return bad_input("--pixel '" + args->pixel + "': expected X,Y (two non-negative integers)");
            RunOptions options = args->run;
            options.select.cases = {args->case_name};
            auto explained = explain_cell(options, args->cell, pixel);
            if (!explained) return bad_input(explained.error().to_string());
            const ExplainedCell& e = *explained;
            if (!args->json.empty()) {
              const std::string text = explanation_json(e).dump(2) + "\n";
              if (args->json == "-") {
                fmt::print("{}", text);
                return 0;
              }
              if (auto ok = write_file_atomically(args->json, text, "the explanation"); !ok) return bad_input(ok.error().to_string());
            }
            const CellResult& r = e.cell;
            fmt::print("{}: {}", r.id(), to_string(r.status));
            if (r.status == CellStatus::fail) fmt::print(" (max error {:.3g}, judged against {})", r.metrics.max_abs, r.reference.label);
            fmt::print("\n");
            if (const auto& d = divergence_of(e)) fmt::print("departs: {}\n", d->kind == "error" ? d->error : d->text);
            fmt::print("\npixel ({}, {}), executed by the shader's double twin{}:\n\n", e.pixel.x, e.pixel.y,
                       e.pixel.against.empty() ? "" : "; each value beside what it matches in " + e.pixel.against);
            fmt::print("{}", twin::listing_text(e.pixel.lines));
            if (!args->json.empty()) fmt::print("\nexplanation: {}\n", args->json);
            return 0;
          }};
}

}  // namespace shaderbed
