#pragma once
// What every console view ends with: the cells that did not pass, each with its message and
// attribution (new failures, errors, known failures with their reasons, known failures
// that passed), then the one totals line.
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

// Sections are separated by a blank line (and preceded by one, if blank_line_first); true
// when anything was printed.
// `colour`: section titles and the totals' verdict tinted (report/ConsoleColour.h).
bool print_problems(const RunReport& report, std::FILE* out, bool blank_line_first = true, bool colour = false);
// "1400 cells: 1398 passed, 1 failed, 1 known, 0 errors in 10.2 s", prefixed "FAIL: " when
// the run is not acceptable, so the verdict is the last thing on the screen.
void print_totals(const RunReport& report, std::FILE* out, bool colour = false);

}  // namespace shaderbed
