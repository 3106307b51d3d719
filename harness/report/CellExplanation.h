#pragma once
// The words every report uses for what a cell was judged against and, when it failed,
// which convention explains the difference (compare/ConventionFit.h computes the fits).
#include <string>

#include "report/Results.h"

namespace shaderbed {

// "hlsl vulkan/spirv (the original)", "images in DIR", "" for a model (the usual case).
std::string judged_against(const CellResult& r);

// The best fitting explanation's summary ("" when none fits): the line a failure shows.
std::string best_explanation(const CellResult& r);

// Why no convention was tried on a failing cell without any explanation: "478 pixels are
// NaN/Inf" (compare/ConventionFit.h withholds fits beside NaN/Inf they do not produce),
// "the render is blank"; "" otherwise.
std::string withheld_explanation(const CellResult& r);

// The tolerance as a formula: "1e-05 + 0.000122|ref|", or "1e-05" when purely absolute.
std::string tolerance_text(double max_abs, double max_rel);

}  // namespace shaderbed
