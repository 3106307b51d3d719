#include "hard/HardOutput.h"

#include <fmt/format.h>

#include "report/JsonValues.h"

namespace shaderbed::hard {
namespace {

std::string ulps_text(const NumericalError& e) { return e.max_ulps_pixel < 0 ? "-" : fmt::format("{}", e.max_ulps); }

nlohmann::json json_values(const std::vector<double>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values) out.push_back(json_number<nlohmann::json>(v));
  return out;
}

nlohmann::json pixel(int index, int width) {
  if (index < 0 || width <= 0) return nullptr;
  return {index % width, index / width};
}

}  // namespace

std::string console_report(const HardReport& report) {
  std::string out;
  std::string current;
  auto summary = [&](const std::string& name) {
    for (const ModelSummary& s : report.summaries) {
      if (s.case_name != name) continue;
      if (s.user) {
        out += fmt::format("  {} against its double twin: {} NaN/Inf ({} where the twin is finite), max rel {:.3g}, "
                           "max ulps {}, {} failed\n",
                           s.case_name, s.book_nonfinite, s.book_mismatch, s.book_max_relative, s.book_max_ulps,
                           s.book_failed);
        continue;
      }
      out += fmt::format("  {} book: {} NaN/Inf ({} where the reference is finite), max rel {:.3g}, max ulps {}, {} failed",
                         s.case_name, s.book_nonfinite, s.book_mismatch, s.book_max_relative, s.book_max_ulps,
                         s.book_failed);
      if (s.has_robust)
        out += fmt::format(" | robust: {} NaN/Inf ({} where the reference is finite), max rel {:.3g}, max ulps {}, {} failed\n",
                           s.robust_nonfinite, s.robust_mismatch, s.robust_max_relative, s.robust_max_ulps, s.robust_failed);
      else
        out += " | robust: not needed\n";
    }
  };
  const std::string header = fmt::format("  {:<22} {:<13} {:<7} {:<5} {:<13} {:>8} {:>8} {:>11} {:>12}  {}\n",
                                         "scenario", "variant", "kind", "lang", "backend/path", "NaN/Inf", "ref n/f",
                                         "max rel", "max ulps", "status");
  const std::string user_header = fmt::format("  {:<22} {:<13} {:<7} {:<5} {:<13} {:>8} {:>8} {:>11} {:>12}  {}\n",
                                              "scenario", "variant", "kind", "lang", "backend/path", "NaN/Inf",
                                              "twin n/f", "max rel", "max ulps", "status");
  for (const HardRow& r : report.rows) {
    if (r.case_name != current) {
      if (!current.empty()) summary(current);
      current = r.case_name;
      if (r.reference == "model") {
        out += fmt::format("\n{}\n{}", current, header);
      } else {
        // A user case: the scenarios (with the parameter ranges they chose), then the rows
        // against the shader's own double twin.
        out += fmt::format("\n{} (against its own shader in double: the twin)\n", current);
        const std::string prefix = current + "/";
        for (const std::string& key : report.scenarios)
          if (key.starts_with(prefix))
            out += fmt::format("  {:<22} {}\n", key.substr(prefix.size()), report.scenario_probes.at(key));
        out += user_header;
      }
    }
    if (r.status == CellStatus::error) {
      out += fmt::format("  {:<22} {:<13} {:<7} {:<5} {:<13} error: {}\n", r.scenario, r.variant, r.kind, r.language,
                         r.backend + "/" + r.path, r.message);
      continue;
    }
    out += fmt::format("  {:<22} {:<13} {:<7} {:<5} {:<13} {:>8} {:>8} {:>11.3g} {:>12}  {}{}\n", r.scenario,
                       r.variant, r.kind, r.language, r.backend + "/" + r.path, r.error.render_nonfinite, r.error.reference_nonfinite,
                       r.error.max_relative, ulps_text(r.error), to_string(r.status),
                       r.message.empty() ? "" : " (" + r.message + ")");
    // The line only where the error is worth explaining (the JSON has it on every row).
    if (r.reference != "model" && r.worst_x >= 0 && (r.error.max_relative > 1e-4 || r.error.nonfinite_mismatch > 0)) {
      if (r.loss)
        out += fmt::format("      worst pixel ({}, {}): loses significance at {}\n", r.worst_x, r.worst_y, r.loss->describe());
      else
        out += fmt::format("      worst pixel ({}, {}): {}\n", r.worst_x, r.worst_y, r.loss_note);
    }
  }
  if (!current.empty()) summary(current);
  size_t failed = 0, errors = 0;
  for (const HardRow& r : report.rows) (r.status == CellStatus::error ? errors : failed) += r.status != CellStatus::pass;
  out += fmt::format("\n{} rows, {} failed, {} errors, {:.1f} s (relative floor {:g}, tolerance {:g}; error not measured "
                     "within {:g} of N.L = 0, N.V = 0, L = -V)\n",
                     report.rows.size(), failed, errors, report.wall_ms / 1000, kRelativeErrorFloor,
                     kRelativeTolerance, kConditioningMargin);
  return out;
}

nlohmann::json json_report(const HardReport& report) {
  nlohmann::json j;
  j["size"] = report.size;
  j["wall_ms"] = report.wall_ms;
  j["relative_floor"] = kRelativeErrorFloor;
  j["relative_tolerance"] = kRelativeTolerance;
  j["conditioning_margin"] = kConditioningMargin;
  j["scenarios"] = nlohmann::json::object();
  for (const auto& [name, probes] : report.scenario_probes) j["scenarios"][name] = probes;
  j["rows"] = nlohmann::json::array();
  for (const HardRow& r : report.rows) {
    const NumericalError& e = r.error;
    const int width = r.width;
    j["rows"].push_back({{"case", r.case_name}, {"scenario", r.scenario}, {"variant", r.variant}, {"kind", r.kind},
                         {"language", r.language}, {"backend", r.backend}, {"path", r.path}, {"status", to_string(r.status)},
                         {"message", r.message}, {"pixels", e.pixels}, {"measured_pixels", e.measured_pixels},
                         {"nan", e.render_nan}, {"inf", e.render_inf}, {"nonfinite", e.render_nonfinite},
                         {"reference_nonfinite", e.reference_nonfinite}, {"nonfinite_mismatch", e.nonfinite_mismatch},
                         {"max_relative", json_number<nlohmann::json>(e.max_relative)}, {"max_relative_pixel", pixel(e.max_relative_pixel, width)},
                         {"max_ulps", e.max_ulps}, {"max_ulps_pixel", pixel(e.max_ulps_pixel, width)},
                         {"reference", r.reference}});
    if (r.reference == "model") continue;
    nlohmann::json& row = j["rows"].back();
    row["worst_pixel"] = r.worst_x < 0 ? nlohmann::json(nullptr) : nlohmann::json{r.worst_x, r.worst_y};
    if (!r.loss) {
      row["significance_loss"] = nullptr;
      row["significance_note"] = r.loss_note;
      continue;
    }
    const twin::SignificanceLoss& l = *r.loss;
    nlohmann::json operands = nlohmann::json::array();
    for (size_t i = 0; i < l.origin.operands.size(); ++i)
      operands.push_back({{"name", l.origin.operands[i].first},
                          {"float", json_values(l.origin.operands[i].second)},
                          {"double", json_values(i < l.exact_operands.size() ? l.exact_operands[i] : std::vector<double>{})}});
    row["significance_loss"] = {{"file", l.origin.file}, {"line", l.origin.line}, {"source", l.origin.source_text},
                                {"operation", l.origin.operation}, {"result", l.origin.result},
                                {"float", json_values(l.origin.values)}, {"double", json_values(l.exact_values)},
                                {"operands", operands},
                                {"relative_error", json_number<nlohmann::json>(l.relative_error)},
                                {"operand_relative_error", json_number<nlohmann::json>(l.operand_relative_error)},
                                {"text", l.describe()}};
  }
  j["models"] = nlohmann::json::array();
  for (const ModelSummary& s : report.summaries) {
    auto side = [](size_t nonfinite, size_t mismatch, double rel, uint64_t ulps, size_t failed) {
      return nlohmann::json{{"nonfinite", nonfinite}, {"nonfinite_mismatch", mismatch}, {"max_relative", json_number<nlohmann::json>(rel)},
                            {"max_ulps", ulps}, {"failed_rows", failed}};
    };
    j["models"].push_back(
        {{"case", s.case_name},
         {"robust", s.has_robust ? "present" : "not needed"},
         {"book", side(s.book_nonfinite, s.book_mismatch, s.book_max_relative, s.book_max_ulps, s.book_failed)},
         {"robust_variant", s.has_robust ? side(s.robust_nonfinite, s.robust_mismatch, s.robust_max_relative,
                                                s.robust_max_ulps, s.robust_failed)
                                         : nlohmann::json(nullptr)}});
  }
  return j;
}

}  // namespace shaderbed::hard
