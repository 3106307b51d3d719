#pragma once
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

// The aligned result table (verdict "pass", "FAIL", "known" or "ERROR"; "min pass" is the
// smallest interior threshold that would have passed; with timing, the draw times), then each new failure with its
// attribution and image paths, the errors, the known failures with their reasons, the
// known failures that passed, and the totals.
struct TableOptions {
  bool timing = false;   // add the draw's timed repeats (wall and driver clock) and build time
};
void print_table(const RunReport& report, std::FILE* out, const TableOptions& options = {});

}  // namespace shaderbed
