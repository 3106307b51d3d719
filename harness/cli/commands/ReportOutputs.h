#pragma once
// The report files `run` and `merge` both write: --json, --junit, --html.
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "report/ConsoleReport.h"
#include "report/HtmlReport.h"
#include "report/Results.h"

namespace shaderbed {

// The console view flags, the same on `run` and `merge`: --table/-v, --timing, --quiet/-q.
void add_console_flags(CLI::App* cmd, ConsoleOptions& console);

struct ReportOutputs {
  std::string json, junit, html;
  std::vector<std::string> charts;   // SVG charts (e.g. from `sweep --chart`) to show in the HTML report
  std::vector<HtmlChart> loaded_charts;

  void add_options(CLI::App* cmd);
  // --json -: the JSON is standard output, so everything else the command says (the console
  // report, where files went) goes to standard error.
  bool json_on_stdout() const { return json == "-"; }
  std::FILE* console() const { return json_on_stdout() ? stderr : stdout; }
  // Reads the --chart files before any work is done; false (after printing why) when one is
  // not a self-contained SVG.
  bool load_charts();
  // Checks every output path can be written, before any work; false after printing why.
  bool check_writable() const;
  // The files write() will write, with their options, for the run to refuse one that is
  // an input: (path, "--json"), ...
  std::vector<std::pair<std::string, std::string>> files() const;
  // False (after printing why) when a report file would be written over one of `inputs`.
  bool check_not_inputs(const std::vector<std::string>& inputs) const;
  // Writes what was asked for; prints where; false (after printing the error) on failure.
  // `html_view` (merge): the report the HTML page shows instead, with `html_notes` on it.
  bool write(const RunReport& report, const RunReport* html_view = nullptr,
             const std::vector<std::string>& html_notes = {}) const;
};

}  // namespace shaderbed
