#include "report/TwinText.h"

#include <fmt/format.h>

#include "report/Markup.h"

namespace shaderbed {

std::vector<std::string> twin_lines(const CellResult& r) {
  if (!r.twin) return {};
  const CellResult::TwinFigures& t = *r.twin;
  if (!t.error.empty()) return {fmt::format("twin ({}): not drawn: {}", t.precision, t.error)};
  using markup::sci;
  std::string line = fmt::format("twin ({}): the render is {} from its shader's twin (worst at {},{}{})", t.precision,
                                 sci(t.max_abs), t.worst_x, t.worst_y,
                                 t.self_error >= 0 ? "; the twin's own error there, against quad precision, " +
                                                         sci(t.self_error)
                                                   : std::string());
  if (t.reference_max_abs >= 0) {
    line += fmt::format(", the twin {} from the reference", sci(t.reference_max_abs));
    // Which half of the error is over the tolerance says whose it is.
    const bool formula = t.reference_max_abs > r.interior_threshold, arithmetic = t.share > 1;
    if (r.status == CellStatus::fail && formula && !arithmetic)
      line += ": the shader computes something else (its exact twin fails too), not fp32 or the driver";
    else if (r.status == CellStatus::fail && arithmetic && !formula)
      line += ": fp32 or the driver (the exact shader passes)";
  }
  std::vector<std::string> lines{line};
  if (!t.nonfinite_origin.empty()) lines.push_back("NaN/Inf first made at " + t.nonfinite_origin);
  return lines;
}

}  // namespace shaderbed
