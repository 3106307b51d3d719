#include "cli/commands/ReportOutputs.h"

#include <cstdio>
#include <filesystem>
#include <tuple>

#include <fmt/format.h>

#include "core/BoundedFile.h"
#include "core/WritablePath.h"
#include "report/HtmlReport.h"
#include "report/JsonReport.h"
#include "report/JunitReport.h"

namespace shaderbed {
namespace {

constexpr size_t kMaxChartBytes = size_t(64) << 20;   // far above any chart sweep draws

}  // namespace

void add_console_flags(CLI::App* cmd, ConsoleOptions& console) {
  auto table = [&console] { console.view = ConsoleView::table; };
  CLI::Option* t = cmd->add_flag_callback("--table", table, "Print every cell's row instead of the summary matrix");
  CLI::Option* v = cmd->add_flag_callback("--verbose,-v", table, "The same as --table");
  CLI::Option* timing = cmd->add_flag("--timing", console.timing,
                "Show each cell's draw time in the table (implies --table): median and 95% confidence interval of the "
                "timed repeats (wall clock and driver clock) and the pipeline build time (the JSON always has them)");
  cmd->add_flag_callback("--quiet,-q", [&console] { console.view = ConsoleView::quiet; },
                         "Print only the cells that did not pass and the totals (no progress off a terminal)")
      ->excludes(t)
      ->excludes(v)
      ->excludes(timing);
}


void ReportOutputs::add_options(CLI::App* cmd) {
  cmd->add_option("--json", json, "Write the results as JSON (schema 2) to this file ('-': standard output, the console report then "
                  "going to standard error)");
  cmd->add_option("--junit", junit, "Write JUnit XML (one testcase per cell) to this file");
  cmd->add_option("--html", html, "Write a self-contained HTML report (index.html) into this folder");
  cmd->add_option("--chart", charts,
                  "An SVG chart to show in the HTML report's \"Speed against error\" section (repeatable), e.g. "
                  "one written by 'shaderbed sweep --chart'")
      ->check(CLI::ExistingFile);
}

bool ReportOutputs::load_charts() {
  loaded_charts.clear();
  for (const std::string& svg : charts) {
    // Bounded, regular files only: `--chart /dev/zero` or a FIFO is one error, not an abort or a wait.
    Result<std::string> read = read_bounded_file(svg, "--chart file", ErrorStage::options, kMaxChartBytes);
    if (!read) {
      fmt::print(stderr, "shaderbed: {}\n", read.error().to_string());
      return false;
    }
    std::string text = std::move(*read);
    // Only a self-contained SVG (gnuplot's, as sweep writes it) may go into the page as it is.
    if (text.find("<svg") == std::string::npos || text.find("<script") != std::string::npos) {
      fmt::print(stderr, "shaderbed: {}: --chart needs an SVG without scripts\n", svg);
      return false;
    }
    loaded_charts.push_back({std::filesystem::path(svg).stem().string(), std::move(text), svg});
  }
  return true;
}

bool ReportOutputs::check_writable() const {
  for (const auto& [path, what, folder] : {std::tuple{json_on_stdout() ? std::string() : json, "--json", false}, std::tuple{junit, "--junit", false},
                                           std::tuple{html, "--html", true}}) {
    if (path.empty()) continue;
    if (auto ok = folder ? check_writable_folder(path, what) : check_writable_file(path, what); !ok) {
      fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
      return false;
    }
  }
  return true;
}

std::vector<std::pair<std::string, std::string>> ReportOutputs::files() const {
  std::vector<std::pair<std::string, std::string>> written;
  if (!json.empty() && !json_on_stdout()) written.emplace_back(json, "--json");
  if (!junit.empty()) written.emplace_back(junit, "--junit");
  if (!html.empty()) written.emplace_back((std::filesystem::path(html) / "index.html").string(), "--html");
  return written;
}

bool ReportOutputs::check_not_inputs(const std::vector<std::string>& inputs) const {
  for (const auto& [path, option] : files())
    if (auto ok = check_not_an_input(path, option, inputs); !ok) {
      fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
      return false;
    }
  return true;
}

bool ReportOutputs::write(const RunReport& report, const RunReport* html_view,
                          const std::vector<std::string>& html_notes) const {
  auto done = [this](const Result<void>& ok, const char* what, const std::string& path) {
    if (!ok) {
      fmt::print(stderr, "shaderbed: {}\n", ok.error().to_string());
      return false;
    }
    fmt::print(console(), "{}: {}\n", what, std::filesystem::absolute(path).string());
    return true;
  };
  bool ok = true;
  if (json_on_stdout()) {
    const std::string text = to_json(report);
    ok &= std::fwrite(text.data(), 1, text.size(), stdout) == text.size() && std::fflush(stdout) == 0;
  } else if (!json.empty()) {
    ok &= done(write_json(report, json), "results", json);
  }
  if (!junit.empty()) ok &= done(write_junit(report, junit), "junit", junit);
  if (!html.empty()) {
    auto written = write_html(html_view ? *html_view : report, html, HtmlOptions{.charts = loaded_charts, .notes = html_notes});
    ok &= done(written ? Result<void>{} : std::unexpected(written.error()), "html",
               (std::filesystem::path(html) / "index.html").string());
  }
  return ok;
}

}  // namespace shaderbed
