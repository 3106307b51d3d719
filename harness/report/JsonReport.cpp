#include "report/JsonReport.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace shaderbed {
namespace {

// JSON has no Inf/NaN: a non-finite metric is written as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

std::string to_json(const RunReport& report) {
  nlohmann::json j;
  j["schema"] = 1;
  j["tool"] = {{"glslang", report.tools.glslang},
               {"spirv_tools", report.tools.spirv_tools},
               {"spirv_cross", report.tools.spirv_cross},
               {"mesa", {{"vulkan", report.tools.vulkan_driver}, {"gl", report.tools.gl_driver}}}};
  j["wall_ms"] = report.wall_ms;
  j["results"] = nlohmann::json::array();
  for (const CellResult& r : report.results) {
    nlohmann::json cell = {{"case", r.case_name}, {"variant", r.variant}, {"language", r.language},
                           {"backend", r.backend}, {"path", r.path},      {"shape", r.shape},
                           {"status", r.status}};
    if (!r.message.empty()) cell["message"] = r.message;
    cell["metrics"] = {{"max_abs", number(r.metrics.max_abs)},
                       {"rmse", number(r.metrics.rmse)},
                       {"psnr", number(r.metrics.psnr)},
                       {"bad_pixels", r.metrics.bad_pixels},
                       {"nonfinite", r.metrics.nonfinite},
                       {"coverage_mismatch", r.metrics.coverage_mismatch},
                       {"silhouette_max_abs", number(r.metrics.silhouette_max_abs)},
                       {"interior_pixels", r.metrics.interior_pixels},
                       {"silhouette_pixels", r.metrics.silhouette_pixels}};
    cell["tolerance"] = {{"interior", r.interior_threshold}, {"silhouette", r.silhouette_threshold}};
    if (!r.lut_derivation.empty()) cell["tolerance"]["lut"] = {{"bound", r.lut_bound}, {"derivation", r.lut_derivation}};
    cell["time_ms"] = r.time_ms;
    if (!r.artefacts.render_exr.empty()) cell["image"] = r.artefacts.render_exr;
    j["results"].push_back(std::move(cell));
  }
  return j.dump(2);
}

Result<void> write_json(const RunReport& report, const std::string& path) {
  std::error_code ec;
  if (const auto parent = std::filesystem::path(path).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent, ec);
  std::ofstream out(path);
  if (!out) return std::unexpected(Error{.message = "cannot write JSON report", .file = path, .stage = "report"});
  out << to_json(report) << '\n';
  if (!out) return std::unexpected(Error{.message = "write failed", .file = path, .stage = "report"});
  return {};
}

}  // namespace shaderbed
