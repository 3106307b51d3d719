#pragma once
// The hard-case report as a console table (per model: one row per scenario, variant,
// language and backend, then a summary line) and as JSON.
//
// JSON schema (`shaderbed hard --json FILE`):
// {
//   "size": 129, "wall_ms": ..., "relative_floor": 1e-3, "relative_tolerance": 1e-2,
//   "conditioning_margin": 1e-4,
//   "scenarios": {"<name>": "<what it probes>", ...},
//   "rows": [{"case", "scenario", "variant", "kind": "book"|"robust", "language", "backend", "path",
//             "status": "pass"|"fail"|"error", "message",
//             "pixels", "measured_pixels", "nan", "inf", "nonfinite", "reference_nonfinite",
//             "nonfinite_mismatch", "max_relative", "max_relative_pixel": [x, y] | null,
//             "max_ulps", "max_ulps_pixel": [x, y] | null,
//             "reference": "model" | "twin-double",
//             user cases (reference "twin-double") also: "worst_pixel": [x, y] | null,
//             "significance_loss": {"file", "line", "source", "operation", "result", "float": [..],
//                                   "double": [..], "operands": [{"name", "float", "double"}, ..],
//                                   "relative_error", "operand_relative_error", "text"} | null,
//             "significance_note" (when null: why)}, ...],
//   (a user case's scenarios are keyed "<case>/<scenario>")
//   "models": [{"case", "robust": "present"|"not needed",
//               "book": {"nonfinite", "nonfinite_mismatch", "max_relative", "max_ulps", "failed_rows"},
//               "robust_variant": {...same...} | null}, ...]
// }
#include <string>

#include <nlohmann/json.hpp>

#include "hard/HardRunner.h"

namespace shaderbed::hard {

std::string console_report(const HardReport&);
nlohmann::json json_report(const HardReport&);

}  // namespace shaderbed::hard
