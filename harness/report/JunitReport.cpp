#include "report/TwinText.h"
#include "report/JunitReport.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "core/AtomicFile.h"
#include "report/CellExplanation.h"
#include "report/FirstLine.h"
#include "report/Markup.h"

namespace shaderbed {
namespace {

using markup::escape;
using markup::sci;

double cell_seconds(const CellResult& r) { return own_ms(r) / 1000.0; }

std::string seconds(double s) { return fmt::format("{:.3f}", s); }

std::string attribution(const CellResult& r) {
  std::string out = "attribution: " + (r.attribution.empty() ? std::string("none") : r.attribution);
  if (!r.attribution_reason.empty()) out += " (" + r.attribution_reason + ")";
  return out;
}

std::string metric_summary(const CellResult& r) {
  const CellMetrics& m = r.metrics;
  std::string out = fmt::format("max_abs {} (threshold {}, smallest passing {}), silhouette {} (threshold {}, smallest passing {}), rmse {}",
                                sci(m.max_abs), tolerance_text(r.interior_threshold, r.interior_threshold_rel),
                                sci(m.min_passing_interior), sci(m.silhouette_max_abs),
                                tolerance_text(r.silhouette_threshold, r.silhouette_threshold_rel),
                                sci(m.min_passing_silhouette), sci(m.rmse));
  if (m.nonfinite_mismatch) out += fmt::format(", {} NaN/Inf mismatches", m.nonfinite_mismatch);
  if (m.coverage_mismatch) out += fmt::format(", {} coverage mismatches", m.coverage_mismatch);
  return out;
}

std::string details(const CellResult& r) {
  const CellMetrics& m = r.metrics;
  std::string out;
  if (!r.message.empty()) out += r.message + "\n";
  out += metric_summary(r) + "\n";
  out += fmt::format("psnr {} dB, {} bad pixels, {} NaN/Inf in the render\n", std::isfinite(m.psnr) ? fmt::format("{:.1f}", m.psnr) : sci(m.psnr),
                     m.bad_pixels, m.nonfinite);
  out += fmt::format("coverage: {} drawn, {} in the reference, {:.1f} expected; {} interior, {} silhouette pixels\n",
                     m.covered_pixels, m.reference_covered_pixels, m.expected_area, m.interior_pixels, m.silhouette_pixels);
  for (const auto& [name, v] : {std::pair{"render", &m.render_values}, std::pair{"reference", &m.reference_values}})
    out += fmt::format("{} values: {} NaN, {} +Inf, {} -Inf, {} negative, {} above one\n", name, v->nan, v->pos_inf,
                       v->neg_inf, v->negative, v->above_one);
  if (!r.lut_derivation.empty()) out += fmt::format("LUT bound {} ({})\n", sci(r.lut_bound), r.lut_derivation);
  if (!r.texel_derivation.empty()) out += fmt::format("texel bound {} ({})\n", sci(r.texel_bound), r.texel_derivation);
  if (!r.tolerance_reason.empty()) out += "tolerance: " + r.tolerance_reason + "\n";
  out += attribution(r) + "\n";
  for (const Explanation& e : r.explanations)
    out += fmt::format("convention {}: {} (residual {}, rmse {}, {} pixels)\n", e.fits ? "fits" : "does not fit",
                       e.summary, sci(e.residual), sci(e.rmse), e.pixels);
  return out;
}

std::string warning_lines(const CellResult& r) {
  std::string out;
  for (const std::string& w : r.warnings) out += "warning: " + w + "\n";
  return out;
}

std::string system_out(const CellResult& r) {
  std::string out = warning_lines(r);
  for (const std::string& line : twin_lines(r)) out += line + "\n";
  for (const auto& [stage, ms] : r.time_ms)
    out += fmt::format("{} {:.3f} ms{}\n", stage, ms, shared_stage(stage) ? " (shared)" : "");
  const CellArtefacts& a = r.artefacts;
  for (const auto& [label, path] : {std::pair{"render", &a.render_png}, std::pair{"error", &a.error_png},
                                    std::pair{"reference", &a.reference_png}, std::pair{"render exr", &a.render_exr},
                                    std::pair{"error exr", &a.error_exr}})
    if (!path->empty()) out += fmt::format("{}: {}\n", label, *path);
  // GitLab's and Jenkins' test views show an image named so (the path as the run wrote it:
  // relative to the directory the run started in, which is where both resolve it).
  for (const std::string* png : {&a.render_png, &a.error_png, &a.reference_png})
    if (!png->empty()) out += fmt::format("[[ATTACHMENT|{}]]\n", *png);
  if (!r.fragment_spirv_hash.empty() || !r.vertex_spirv_hash.empty())
    out += fmt::format("spirv hash: vertex {} fragment {}\n", r.vertex_spirv_hash, r.fragment_spirv_hash);
  return out;
}

struct Counts {
  size_t tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0;
  void add(const CellResult& r) {
    ++tests;
    seconds += cell_seconds(r);
    if (r.status == CellStatus::error) ++errors;
    else if ((r.status == CellStatus::fail && r.known_failure) || r.status == CellStatus::skipped) ++skipped;
    else if (r.status != CellStatus::pass) ++failures;
  }
  // <testsuites> takes no `skipped` in the junit-10 schema CI systems validate against
  // (tests/schema/junit-10.xsd); <testsuite> does.
  std::string attributes(bool with_skipped = true) const {
    std::string out = fmt::format("tests=\"{}\" failures=\"{}\" errors=\"{}\"", tests, failures, errors);
    if (with_skipped) out += fmt::format(" skipped=\"{}\"", skipped);
    return out;
  }
};

}  // namespace

std::string to_junit(const RunReport& report) {
  // Suites in first-appearance order of their case.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const CellResult*>> suites;
  Counts total;
  for (const CellResult& r : report.results) {
    if (!suites.contains(r.case_name)) order.push_back(r.case_name);
    suites[r.case_name].push_back(&r);
    total.add(r);
  }
  const ToolVersions& t = report.tools;
  const std::pair<const char*, const std::string*> properties[] = {
      {"glslang", &t.glslang},         {"spirv_tools", &t.spirv_tools},     {"spirv_cross", &t.spirv_cross},
      {"llvm", &t.llvm},               {"mesa_vulkan", &t.vulkan_driver},   {"mesa_gl", &t.gl_driver},
      {"gl_platform", &t.gl_platform},
      {"shard", &report.shard},        {"out_dir", &report.out_dir}};

  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"shaderbed\" {} time=\"{}\">\n", total.attributes(false), seconds(report.wall_ms / 1000.0));
  for (const std::string& name : order) {
    Counts counts;
    for (const CellResult* r : suites[name]) counts.add(*r);
    x += fmt::format("  <testsuite name=\"{}\" {} time=\"{}\">\n", escape(name, true), counts.attributes(),
                     seconds(counts.seconds));
    x += "    <properties>\n";
    for (const auto& [key, value] : properties)
      x += fmt::format("      <property name=\"{}\" value=\"{}\"/>\n", key, escape(*value, true));
    x += "    </properties>\n";
    for (const CellResult* rp : suites[name]) {
      const CellResult& r = *rp;
      x += fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{}\">\n",
                       escape(r.case_name + "." + r.variant + "." + r.language, true),
                       escape(r.backend + "/" + r.path + "/" + r.shape, true), seconds(cell_seconds(r)));
      if (r.status == CellStatus::error) {
        x += fmt::format("      <error type=\"error\" message=\"{}\">{}</error>\n", escape(first_line(r.message), true),
                         escape(r.message));
      } else if (r.status == CellStatus::skipped) {
        x += fmt::format("      <skipped message=\"{}\"/>\n", escape("does not apply: " + first_line(r.message), true));
      } else if (r.status == CellStatus::fail && r.known_failure) {
        x += fmt::format("      <skipped message=\"{}\">{}</skipped>\n", escape("known: " + r.known_reason, true),
                         escape(details(r)));
      } else if (r.status != CellStatus::pass) {
        std::string message = r.message.empty() ? "" : first_line(r.message) + "; ";
        if (const std::string best = best_explanation(r); !best.empty()) message += "explained: " + best + "; ";
        message += metric_summary(r) + "; " + attribution(r);
        if (const std::string against = judged_against(r); !against.empty()) message += "; judged against " + against;
        x += fmt::format("      <failure type=\"{}\" message=\"{}\">{}</failure>\n",
                         escape(r.attribution.empty() ? "fail" : r.attribution, true), escape(message, true),
                         escape(details(r)));
      }
      // A CI's test view shows a failure's context; a passing case's would be most of the
      // file, so it gets its warnings only.
      if (r.status != CellStatus::pass) {
        x += fmt::format("      <system-out>{}</system-out>\n", escape(system_out(r)));
      } else if (!r.warnings.empty()) {
        x += fmt::format("      <system-out>{}</system-out>\n", escape(warning_lines(r)));
      }
      x += "    </testcase>\n";
    }
    x += "  </testsuite>\n";
  }
  x += "</testsuites>\n";
  return x;
}

Result<void> write_junit(const RunReport& report, const std::string& path) {
  return write_file_atomically(path, to_junit(report), "JUnit report");
}

}  // namespace shaderbed
