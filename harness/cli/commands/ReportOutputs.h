#pragma once
// The report files `run` and `merge` both write: --json, --junit, --html.
#include <string>

#include <CLI/CLI.hpp>

#include "report/Results.h"

namespace shaderbed {

struct ReportOutputs {
  std::string json, junit, html;

  void add_options(CLI::App* cmd);
  // Writes what was asked for; prints where; false (after printing the error) on failure.
  bool write(const RunReport& report) const;
};

}  // namespace shaderbed
