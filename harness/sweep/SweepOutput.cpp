#include "sweep/SweepOutput.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "report/JsonValues.h"
#include "report/Markup.h"

namespace shaderbed {
namespace {

using ojson = nlohmann::ordered_json;


std::string axis_text(const SweepPoint& p) {
  std::string s;
  for (const auto& [name, value] : p.axis_values) s += fmt::format("{}={} ", name, format_axis_value(value));
  return s.empty() ? "-" : s.substr(0, s.size() - 1);
}

// An SH case's sweep: its errors are against the exact lighting integral, and its points
// carry the approximation's own costs.
bool is_sh_sweep(const SweepResult& sweep) {
  return std::any_of(sweep.points.begin(), sweep.points.end(),
                     [](const SweepPoint& p) { return p.precompute_ms > 0 || p.bytes_per_vertex > 0; });
}

}  // namespace

void print_sweep_table(const SweepResult& sweep, std::FILE* out) {
  using markup::sci;
  const std::vector<std::string> headers = {"point", "variant", "precision", "lang", "backend", "path", "shape",
                                            "rmse", "max err", "draw ms [CI]", "driver ms", "instr", "pareto", "within tol."};
  // SH cases: what the approximation costs besides the draw (the same for every band count).
  const bool sh = is_sh_sweep(sweep);
  std::vector<std::string> header_row = headers;
  if (sh) header_row.insert(header_row.end() - 2, {"precompute ms", "bytes/vertex"});
  std::vector<std::vector<std::string>> rows;
  for (const SweepPoint& p : sweep.points) {
    rows.push_back({axis_text(p), p.cell.at("variant"), p.cell.at("precision"), p.cell.at("language"),
                    p.cell.at("backend"), p.cell.at("path"), p.cell.at("shape"), sci(p.rmse), sci(p.max_abs),
                    fmt::format("{:.3f} [{:.3f}, {:.3f}]", p.time_ms, p.time_low_ms, p.time_high_ms),
                    fmt::format("{:.3f}", p.driver_clock_ms), std::to_string(p.instructions), p.pareto ? "*" : "",
                    p.status == CellStatus::error ? "ERROR" : p.status == CellStatus::pass ? "yes" : "no"});
    if (sh) rows.back().insert(rows.back().end() - 2, {fmt::format("{:.1f}", p.precompute_ms), fmt::format("{:.0f}", p.bytes_per_vertex)});
  }
  std::vector<size_t> width(header_row.size());
  for (size_t c = 0; c < header_row.size(); ++c) width[c] = header_row[c].size();
  for (const auto& row : rows)
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  const auto print_row = [&](const std::vector<std::string>& row) {
    std::string line;
    for (size_t c = 0; c < row.size(); ++c) line += fmt::format("{:<{}}  ", row[c], width[c]);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print(out, "{}\n", line);
  };
  print_row(header_row);
  for (const auto& row : rows) print_row(row);
  for (const SweepPoint& p : sweep.points)
    if (p.status == CellStatus::error) fmt::print(out, "\nerror at {} {}: {}\n", axis_text(p), p.cell.at("variant"), p.message);
  fmt::print(out,
             "\n{} points of {} at {}x{}; draw time = wall median of {} timed draws after {} warm-up (CI: the "
             "median's, order statistics); rmse and max err over interior pixels against {}; instr = SPIR-V instructions "
             "(vertex + fragment); * = on the Pareto front of time against rmse; within tol. = within the case's "
             "tolerance{}\n",
             sweep.points.size(), sweep.case_name, sweep.size, sweep.size, sweep.timing.runs, sweep.timing.warmup,
             sh ? "the exact lighting integral (truncation, rays and compression; precompute ms is 0 when the transfer "
                  "came from the cache)"
                : "the per-pixel model in double",
             sh ? " (the shader against the truncated SH, and the approximation within its bound)" : " against that reference");
}

std::string sweep_json(const SweepResult& sweep, const std::vector<SceneChart>& charts) {
  ojson j;
  j["case"] = sweep.case_name;
  j["size"] = sweep.size;
  j["timing"] = {{"warmup", sweep.timing.warmup}, {"runs", sweep.timing.runs}};
  ojson axes = ojson::array();
  for (const SweepAxis& a : sweep.axes) axes.push_back({{"name", a.name}, {"values", a.values}});
  j["axes"] = std::move(axes);
  j["precisions"] = sweep.precisions;
  // A sweep stopped by a signal keeps the points it finished, and says so.
  j["interrupted"] = !sweep.interrupted_by.empty();
  if (!sweep.interrupted_by.empty()) j["interrupted_by"] = sweep.interrupted_by;
  j["steps_done"] = sweep.steps_done;
  j["steps_planned"] = sweep.steps_planned;
  j["tools"] = json_tools(sweep.cells.tools);
  ojson points = ojson::array();
  for (const SweepPoint& p : sweep.points) {
    ojson params = ojson::object();
    for (const auto& [name, value] : p.axis_values) params[name] = json_number(value);
    for (const char* key : {"variant", "precision", "language", "backend", "path", "shape"}) params[key] = p.cell.at(key);
    points.push_back({{"params", std::move(params)},
                      {"rmse", json_number(p.rmse)},
                      {"max_abs", json_number(p.max_abs)},
                      {"time_ms", json_number(p.time_ms)},
                      {"time_ci_ms", {json_number(p.time_low_ms), json_number(p.time_high_ms)}},
                      {"driver_clock_ms", json_number(p.driver_clock_ms)},
                      {"build_ms", json_number(p.build_ms)},
                      {"precompute_ms", json_number(p.precompute_ms)},
                      {"bytes_per_vertex", json_number(p.bytes_per_vertex)},
                      {"instructions", p.instructions},
                      {"instructions_by_stage", {{"vertex", p.vertex_instructions}, {"fragment", p.fragment_instructions}}},
                      {"status", to_string(p.status)},
                      {"message", p.message},
                      {"series", p.series},
                      {"label", p.label},
                      {"scene", p.scene},
                      {"pareto", p.pareto}});
  }
  j["points"] = std::move(points);
  ojson chart_list = ojson::array();
  for (const SceneChart& c : charts) chart_list.push_back({{"scene", c.scene}, {"png", c.files.png}, {"svg", c.files.svg}});
  j["charts"] = std::move(chart_list);
  return j.dump(2) + "\n";
}

Result<std::vector<SceneChart>> write_sweep_charts(const SweepResult& sweep, const std::string& out_stem) {
  std::vector<std::string> scenes;
  for (const SweepPoint& p : sweep.points)
    if (p.status != CellStatus::error && std::find(scenes.begin(), scenes.end(), p.scene) == scenes.end()) scenes.push_back(p.scene);
  if (scenes.empty()) return fail(ErrorStage::sweep, "no point was drawn: nothing to chart");
  const auto& c = sweep.points.front().cell;
  const std::string cells = fmt::format("{}, {}, {}", c.at("language"), c.at("backend"), c.at("shape"));
  std::vector<SceneChart> charts;
  for (size_t i = 0; i < scenes.size(); ++i) {
    std::vector<ChartPoint> points;
    for (const SweepPoint& p : sweep.points)
      if (p.status != CellStatus::error && p.scene == scenes[i])
        points.push_back({p.label, p.series, p.time_ms, p.rmse, p.time_low_ms, p.time_high_ms});
    const std::string scene = scenes[i].empty() ? "" : ", " + scenes[i];
    const ChartSpec spec{.title = fmt::format("{}{}: speed against error ({}, {}x{})", sweep.case_name, scene, cells,
                                              sweep.size, sweep.size),
                         .x_label = fmt::format("draw time, wall median of {} runs (ms); bars: its confidence interval",
                                                sweep.timing.runs),
                         .y_label = is_sh_sweep(sweep) ? "interior RMSE against the exact lighting integral"
                                                       : "interior RMSE against the per-pixel model in double"};
    const std::string stem = scenes.size() == 1 ? out_stem : fmt::format("{}-{}", out_stem, i + 1);
    auto files = write_speed_error_chart(points, spec, stem);
    if (!files) return std::unexpected(files.error());
    charts.push_back({scenes[i], std::move(*files)});
  }
  return charts;
}

}  // namespace shaderbed
