#pragma once
// The CPU reference rasteriser's time against the drivers' draw of the same scene at the
// same resolution, measured side by side in one run: the reference render repeated and
// its median taken, and the same cell drawn on lavapipe and llvmpipe by the runner with
// timed repeats (the wall median of the draw alone, without the pipeline build).
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed::bench {

struct ComparedCell {
  std::string case_name, variant, shape;
  std::string label() const { return case_name + "/" + variant + "/" + shape; }
};

// "phong/pixel/sphere"
Result<ComparedCell> parse_compared_cell(const std::string& text);

// An error when the cell's case, variant or shape does not exist, so a typo is reported
// before the long suite rather than after it.
Result<void> check_compared_cell(const ComparedCell& cell, const std::string& cases_dir);

struct DriverDraw {
  std::string backend, path, language;
  std::string driver;        // "lavapipe", "llvmpipe"
  TimingInterval wall;       // per draw, ms
  double reference_ratio = 0;   // reference median / this draw's median
};

struct ReferenceVsDrivers {
  ComparedCell cell;
  int size = 0;
  TimingInterval reference;  // per render, ms
  int runs = 0;              // timed repeats of each, after one untimed
  std::vector<DriverDraw> draws;   // lavapipe, llvmpipe's paths, then the shader's double twin
  double twin_of_lavapipe = 0;     // the twin's draw (one thread) / lavapipe's (0: not measured)
};

// The twin's goal (docs/twin.md): its draw on one thread within this many of lavapipe's.
constexpr double twin_draw_goal = 20;

struct SpeedComparisonOptions {
  std::string cases_dir;     // "" = the library's
  int size = 256;
  int runs = 9;              // 9 gives a 96 % interval for the median
  // The language whose shaders reach the drivers: GLSL is the one language with all
  // three GL paths, so every way into llvmpipe is timed.
  std::string language = "glsl";
};

Result<ReferenceVsDrivers> time_reference_against_drivers(const ComparedCell& cell,
                                                          const SpeedComparisonOptions& options);

}  // namespace shaderbed::bench
