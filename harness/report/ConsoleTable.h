#pragma once
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

// The aligned per-cell table, one row per cell (verdict "pass", "FAIL", "known" or
// "ERROR"; "min pass" is the smallest interior threshold that would have passed; with
// timing, the draw times and a note on reading them). `run --table` shows it; the
// failures and totals under it are ConsoleProblems'.
struct TableOptions {
  bool timing = false;   // add the draw's timed repeats (wall and driver clock) and build time
  bool colour = false;   // tint the verdicts as the summary does (report/ConsoleColour.h)
};
void print_table(const RunReport& report, std::FILE* out, const TableOptions& options = {});

}  // namespace shaderbed
