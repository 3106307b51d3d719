#pragma once
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

// The summary matrix (report/SummaryMatrix) as aligned text: one row per case/variant, one
// column per language x backend/path (headed in three lines: language, backend, path),
// each "passed/total" with "!" for new failures or errors and "*" for known ones, then the
// row's worst interior error and its largest share of a threshold, and a legend. It fits a
// screen where the per-cell table (ConsoleTable) is 1400 rows long.
// `colour`: the verdicts tinted (report/ConsoleColour.h).
void print_summary(const RunReport& report, std::FILE* out, bool colour = false);

}  // namespace shaderbed
