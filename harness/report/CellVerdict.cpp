#include "report/CellVerdict.h"

#include <fmt/format.h>

namespace shaderbed {
namespace {

std::string px(double v) { return fmt::format("{:.0f}", v); }

std::string bound(double max_abs, double max_rel) {
  return max_rel > 0 ? fmt::format("{:.3g} + {:.3g}|ref|", max_abs, max_rel) : fmt::format("{:.3g}", max_abs);
}

}  // namespace

size_t coverage_allowance(size_t silhouette_band_pixels) { return 8 + silhouette_band_pixels / 8; }

std::vector<std::string> failed_checks(const CellMetrics& m, const ComparisonThresholds& t, const PixelsOver* over) {
  // Coverage counts: the render against the reference and the mesh's projected area, and
  // the reference against the projected area.
  const size_t allow = coverage_allowance(m.silhouette_pixels);
  const auto off = [allow](double a, double b) { return !(std::abs(a - b) <= double(allow)); };
  const double covered = double(m.covered_pixels), ref_covered = double(m.reference_covered_pixels);
  const double expected_area = m.expected_area > 0 ? m.expected_area : 0;
  const bool blank = m.covered_pixels == 0 && m.reference_covered_pixels > 0;
  const bool render_off = off(covered, ref_covered) || (expected_area > 0 && off(covered, expected_area));
  const bool reference_off = expected_area > 0 && off(ref_covered, expected_area);

  std::vector<std::string> reasons;
  const std::string expected = expected_area > 0 ? fmt::format(", expected ≈{} px", px(expected_area)) : "";
  if (m.interior_pixels == 0) reasons.push_back("reference covers no interior pixels (nothing to compare)");
  if (blank)
    reasons.push_back(fmt::format("blank image: coverage 0 px, reference {} px{}", m.reference_covered_pixels, expected));
  else if (render_off)
    reasons.push_back(fmt::format("coverage {} px, reference {} px{} (allowed ±{})", m.covered_pixels,
                                  m.reference_covered_pixels, expected, allow));
  if (reference_off && !render_off)
    reasons.push_back(fmt::format("reference coverage {} px, expected ≈{} px (allowed ±{}): the reference is off",
                                  m.reference_covered_pixels, px(expected_area), allow));
  else if (reference_off)
    reasons.push_back("the reference's coverage is off the expected area too");
  if (m.nonfinite_mismatch)
    reasons.push_back(fmt::format("{} pixels NaN/Inf where the reference is finite or the reverse (fails at any tolerance)",
                                  m.nonfinite_mismatch));
  if (!blank) {
    if (m.coverage_mismatch) reasons.push_back(fmt::format("coverage differs at {} pixels", m.coverage_mismatch));
    if (over && over->interior)
      reasons.push_back(fmt::format("{} interior pixels over {} (max {:.3g})", over->interior,
                                    bound(t.interior_max_abs, t.interior_max_rel), over->interior_max));
    if (over && over->silhouette)
      reasons.push_back(fmt::format("{} silhouette pixels over {} (max {:.3g})", over->silhouette,
                                    bound(t.silhouette_max_abs, t.silhouette_max_rel), over->silhouette_max));
  }
  if (!reasons.empty()) return reasons;
  // What a report keeps of the pixels over the tolerance. Right after a comparison these
  // add nothing (every bad pixel is over, uncovered or non-finite, each a reason above);
  // for a cell read back from a file they are the whole evidence. Written as `!(x <= limit)`
  // so a NaN fails.
  const bool interior_over = !(m.tolerance_share <= 1) ||
                             (t.interior_max_rel == 0 &&
                              !(tolerance_share(m.max_abs, 0, t.interior_max_abs, 0) <= 1));
  if (interior_over)
    reasons.push_back(fmt::format("interior max {:.3g} over {} (largest share of the tolerance {:.3g})", m.max_abs,
                                  bound(t.interior_max_abs, t.interior_max_rel), m.tolerance_share));
  if (t.silhouette_max_rel == 0 && !(tolerance_share(m.silhouette_max_abs, 0, t.silhouette_max_abs, 0) <= 1))
    reasons.push_back(fmt::format("silhouette max {:.3g} over {}", m.silhouette_max_abs,
                                  bound(t.silhouette_max_abs, t.silhouette_max_rel)));
  if (m.bad_pixels)
    reasons.push_back(fmt::format("{} bad pixels (over the tolerance, uncovered or non-finite)", m.bad_pixels));
  return reasons;
}

ComparisonThresholds tolerance_of(const CellResult& r) {
  return {r.interior_threshold, r.silhouette_threshold, r.interior_threshold_rel, r.silhouette_threshold_rel};
}

bool sh_approximation_exceeded(const CellResult::ShErrors& e) { return e.bound >= 0 && e.truncation > e.bound; }

std::vector<std::string> rejudge_failures(const CellResult& r) {
  std::vector<std::string> reasons = failed_checks(r.metrics, tolerance_of(r));
  if (r.sh && sh_approximation_exceeded(*r.sh))
    reasons.push_back(fmt::format("the SH approximation differs from the exact lighting integral by {:.3g} > {:.3g}",
                                  r.sh->truncation, r.sh->bound));
  return reasons;
}

}  // namespace shaderbed
