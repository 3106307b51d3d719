#pragma once
// The error image a person looks at: each pixel's largest channel |render - reference| in
// the false colours of report/ErrorScale.h, on a linear scale from 0 to the cell's own top
// (report/Results.h ErrorMapScale), so a failure 100x over its threshold shows where it is
// worst instead of saturating, and the report can print the scale's numbers beside it.
// The exact values stay in the .error.exr.
#include <cstdint>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Image.h"
#include "report/Results.h"

namespace shaderbed {

struct ErrorMap {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;   // rows top to bottom
  ErrorMapScale scale;
};

// `error` as compare_images() makes it (coverage = PixelClass): interior and silhouette
// pixels coloured by their error (a NaN/Inf mismatch in the non-finite colour), background
// pixels in write_png()'s background colour. `threshold`: the absolute interior threshold.
ErrorMap error_map(const Image& error, double threshold);

Result<void> write_error_map(const std::string& path, const ErrorMap& map);

}  // namespace shaderbed
