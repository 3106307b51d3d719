#include "report/ConsoleReport.h"

#include <cstdio>

#include "report/ConsoleProblems.h"
#include "report/ConsoleSummary.h"
#include "report/ConsoleTable.h"

namespace shaderbed {

void print_console_report(const RunReport& report, std::FILE* out, const ConsoleOptions& options) {
  ConsoleView view = options.view;
  if (view == ConsoleView::summary && options.timing) view = ConsoleView::table;
  if (view == ConsoleView::table) print_table(report, out, {.timing = options.timing, .colour = options.colour});
  if (view == ConsoleView::summary) print_summary(report, out, options.colour);
  const bool problems = print_problems(report, out, view != ConsoleView::quiet, options.colour);
  if (view != ConsoleView::quiet || problems) std::fputc('\n', out);
  print_totals(report, out, options.colour);
}

}  // namespace shaderbed
