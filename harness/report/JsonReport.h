#pragma once
#include <string>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// {"schema": 1, "tool": {...versions}, "results": [{case, variant, language, backend,
//  path, shape, status, metrics: {max_abs, rmse, psnr, bad_pixels, nonfinite, ...},
//  time_ms: {...}}]}
std::string to_json(const RunReport& report);
Result<void> write_json(const RunReport& report, const std::string& path);

}  // namespace shaderbed
