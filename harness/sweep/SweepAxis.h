#pragma once
// One axis of a sweep: a case parameter (or `tessellation`, the shapes' slices) and the
// values it takes, parsed from NAME=LO:HI:STEPS[:lin|:log]. Steps are spaced
// geometrically when LO > 0 and HI/LO >= 8 (LUT sizes, tessellation, roughness over
// decades), else linearly; ":lin" or ":log" chooses. Integer axes (lut_size, lut_rows,
// tessellation) are rounded, and repeated values dropped.
#include <string>
#include <vector>

#include "core/Error.h"

namespace shaderbed {

struct SweepAxis {
  std::string name;
  std::vector<double> values;
  bool integer = false;
};

// The axes that are not case parameters.
inline constexpr const char* kTessellationAxis = "tessellation";

Result<SweepAxis> parse_sweep_axis(const std::string& text);

// "8", "0.25", "1e-3": how a value appears in labels and --param overrides.
std::string format_axis_value(double value);

}  // namespace shaderbed
