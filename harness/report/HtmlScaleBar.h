#pragma once
// The legend under a failure card's error image: the error map's colour ramp
// (report/ErrorScale.h) as a bar the image's width, with 0 at its left, the scale's top at
// its right, a tick where the interior threshold falls, and the NaN/Inf colour. Its data-*
// attributes carry the numbers and colours it was drawn from, for readers and for tests.
#include <string>

#include "report/Results.h"

namespace shaderbed {

// "" when the cell's error map has no recorded scale (a results file from before it was).
std::string html_error_scale_bar(const CellResult& r);

}  // namespace shaderbed
