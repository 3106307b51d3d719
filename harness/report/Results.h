#pragma once
// The results model every report reads: one CellResult per case x variant x language x
// backend x path x shape, plus the toolchain that produced them.
#include <map>
#include <string>
#include <vector>

namespace shaderbed {

struct CellMetrics {
  double max_abs = 0;               // interior
  double rmse = 0;                  // interior
  double psnr = 0;                  // interior, peak 1
  size_t bad_pixels = 0;            // interior + silhouette
  size_t nonfinite = 0;
  size_t coverage_mismatch = 0;
  double silhouette_max_abs = 0;
  size_t interior_pixels = 0;
  size_t silhouette_pixels = 0;
};

struct CellResult {
  std::string case_name, variant, language, backend, path, shape;
  std::string status;               // "pass", "fail" or "error"
  std::string message;              // why it failed / the error line
  CellMetrics metrics;
  double interior_threshold = 0;    // the case's tolerance
  double silhouette_threshold = 0;
  double lut_bound = 0;             // LUT variants: the derived LUT error bound in the threshold
  std::string lut_derivation;
  std::map<std::string, double> time_ms;   // compile, build, draw, readback, reference, compare
  std::string image;                // path of the render's EXR, if written
};

struct ToolVersions {
  std::string glslang, spirv_tools, spirv_cross, vulkan_driver, gl_driver;
};

struct RunReport {
  ToolVersions tools;
  std::vector<CellResult> results;
  double wall_ms = 0;
  std::string out_dir;

  size_t count(const std::string& status) const {
    size_t n = 0;
    for (const CellResult& r : results) n += r.status == status;
    return n;
  }
};

}  // namespace shaderbed
