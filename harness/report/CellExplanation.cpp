#include "report/CellExplanation.h"

#include <fmt/format.h>

namespace shaderbed {

std::string judged_against(const CellResult& r) {
  const ReferenceSource& s = r.reference;
  if (s.kind == "render") return "the original, " + s.label;
  if (s.kind == "images")
    return s.label + (s.toolchain_note.empty() ? "" : " — drawn by another toolchain: " + s.toolchain_note);
  return "";
}

std::string best_explanation(const CellResult& r) {
  for (const Explanation& e : r.explanations)
    if (e.fits) return e.summary;
  return "";
}

std::string withheld_explanation(const CellResult& r) {
  if (!r.explanations.empty()) return "";
  const CellMetrics& m = r.metrics;
  if (m.nonfinite_mismatch > 0)
    return fmt::format("{} pixel{} NaN/Inf", m.nonfinite_mismatch, m.nonfinite_mismatch == 1 ? " is" : "s are");
  if (m.covered_pixels == 0 && m.reference_covered_pixels > 0) return "the render is blank";
  return "";
}

std::string tolerance_text(double max_abs, double max_rel) {
  return max_rel > 0 ? fmt::format("{:.3g} + {:.3g}|ref|", max_abs, max_rel) : fmt::format("{:.3g}", max_abs);
}

}  // namespace shaderbed
