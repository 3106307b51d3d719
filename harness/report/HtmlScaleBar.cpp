#include "report/HtmlScaleBar.h"

#include <algorithm>

#include <fmt/format.h>

#include "report/ErrorScale.h"
#include "report/Markup.h"

namespace shaderbed {

std::string html_error_scale_bar(const CellResult& r) {
  const ErrorMapScale& s = r.artefacts.error_scale;
  if (!(s.top > 0)) return "";
  using markup::sci;
  // Where the threshold sits on the bar, 0-100 %; the top is never below the threshold.
  const double at = std::clamp(100.0 * r.interior_threshold / s.top, 0.0, 100.0);
  const bool top_is_threshold = s.peak < r.interior_threshold;
  std::string stops;
  for (const Rgb8& c : kErrorScaleStops) stops += (stops.empty() ? "" : " ") + css_colour(c);
  return fmt::format(
      "<div class=\"scale\" data-top=\"{}\" data-threshold=\"{}\" data-peak=\"{}\" data-peak-x=\"{}\" data-peak-y=\"{}\" "
      "data-stops=\"{}\" data-nonfinite=\"{}\">"
      "<div class=\"bar\" style=\"background:{}\"><i class=\"tick\" style=\"left:{:.2f}%\"></i></div>"
      "<div class=\"nums\"><span class=\"lo\">0</span><span class=\"hi\">{}</span></div>"
      "<div class=\"legend\">top: {}; <i class=\"tick\"></i> threshold {}{} &middot; "
      "<i class=\"sw\" style=\"background:{}\"></i> NaN/Inf</div></div>",
      sci(s.top), sci(r.interior_threshold), sci(s.peak), s.peak_x, s.peak_y, stops, css_colour(kErrorNonFinite),
      error_scale_gradient(), at, sci(s.top),
      top_is_threshold ? std::string("the threshold (every interior error is below it)")
      : r.interior_threshold > 0
          ? fmt::format("the worst interior error, {:.3g}&times; the threshold", s.peak / r.interior_threshold)
          : std::string("the worst interior error"),
      sci(r.interior_threshold), r.interior_threshold_rel > 0 ? " (+ relative part)" : "", css_colour(kErrorNonFinite));
}

}  // namespace shaderbed
