#pragma once
// What `run` and `merge` print on stdout once the cells are done: a view of the run, then
// the cells that did not pass and the totals (report/ConsoleProblems).
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

enum class ConsoleView {
  summary,   // the case/variant x language/backend/path matrix (the default: fits a screen)
  table,     // every cell's row (--table, --verbose)
  quiet,     // nothing but the problems and the totals (--quiet)
};

struct ConsoleOptions {
  ConsoleView view = ConsoleView::summary;
  bool timing = false;   // per-cell draw times; they live in the table, so they select it over the summary
  bool colour = false;   // ANSI colour on the verdicts (report/ConsoleColour.h)
};

void print_console_report(const RunReport& report, std::FILE* out, const ConsoleOptions& options = {});

}  // namespace shaderbed
