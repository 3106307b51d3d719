#pragma once
// The comparison tests' thresholds: 1e-5 inside the silhouette, 1e-2 on it.
#include "compare/ImageComparison.h"

namespace shaderbed::test {

inline const ComparisonThresholds kThresholds{1e-5, 1e-2};

}  // namespace shaderbed::test
