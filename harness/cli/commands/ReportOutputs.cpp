#include "cli/commands/ReportOutputs.h"

#include <filesystem>

#include <fmt/format.h>

#include "report/HtmlReport.h"
#include "report/JsonReport.h"
#include "report/JunitReport.h"

namespace shaderbed {

void ReportOutputs::add_options(CLI::App* cmd) {
  cmd->add_option("--json", json, "Write the results as JSON (schema 2) to this file");
  cmd->add_option("--junit", junit, "Write JUnit XML (one testcase per cell) to this file");
  cmd->add_option("--html", html, "Write a self-contained HTML report (index.html) into this folder");
}

bool ReportOutputs::write(const RunReport& report) const {
  auto done = [](const Result<void>& ok, const char* what, const std::string& path) {
    if (!ok) {
      fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
      return false;
    }
    fmt::print("{}: {}\n", what, std::filesystem::absolute(path).string());
    return true;
  };
  bool ok = true;
  if (!json.empty()) ok &= done(write_json(report, json), "results", json);
  if (!junit.empty()) ok &= done(write_junit(report, junit), "junit", junit);
  if (!html.empty()) ok &= done(write_html(report, html), "html", (std::filesystem::path(html) / "index.html").string());
  return ok;
}

}  // namespace shaderbed
