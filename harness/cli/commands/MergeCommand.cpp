// `shaderbed merge A.json B.json ...`: joins shard results into one report, in the same
// canonical order as one whole run.
#include <memory>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/commands/Command.h"
#include "cli/commands/ReportOutputs.h"
#include "run/Runner.h"
#include "report/ConsoleReport.h"
#include "report/JsonReport.h"
#include "report/RunCoverage.h"
#include "report/ShardMerge.h"

namespace shaderbed {
namespace {

struct MergeArguments {
  std::vector<std::string> inputs;
  ReportOutputs outputs;
  ConsoleOptions console;
};

}  // namespace

Command add_merge_command(CLI::App& app) {
  auto args = std::make_shared<MergeArguments>();
  CLI::App* cmd = app.add_subcommand("merge", "Join the JSON results of shards (or CI matrix jobs) into one report");
  cmd->add_option("results", args->inputs, "JSON result files written by 'shaderbed run --json'")->required();
  args->outputs.add_options(cmd);
  add_console_flags(cmd, args->console);
  return {cmd, [args] {
            if (!args->outputs.load_charts() || !args->outputs.check_writable()) return kExitBadInput;
            std::vector<RunReport> parts;
            for (const std::string& path : args->inputs) {
              auto part = read_json(path);
              if (!part) {
                fmt::print(stderr, "shaderbed: {}\n", part.error().to_string());
                return kExitBadInput;
              }
              parts.push_back(std::move(*part));
            }
            auto joined = merge_shards(std::move(parts), args->inputs);
            if (!joined) {
              fmt::print(stderr, "shaderbed: {}\n", joined.error().to_string());
              return kExitBadInput;
            }
            RunReport& merged = *joined;
            const RunCoverage coverage = run_coverage(merged);
            if (args->console.view != ConsoleView::quiet) fmt::print("merged {} file{}: {} cells of {} case{}\n", args->inputs.size(), args->inputs.size() == 1 ? "" : "s",
                       merged.results.size(), coverage.cases, coverage.cases == 1 ? "" : "s");
            if (args->console.view != ConsoleView::quiet)
              for (const std::string& line : coverage.lines) fmt::print("  {}\n", line);
            if (!coverage.holes.empty())
              fmt::print("  no cells for {}: was a job of the matrix left out?\n", fmt::join(coverage.holes, ", "));
            print_console_report(merged, stdout, args->console);
            if (!args->outputs.write(merged)) return kExitFail;
            return merged.acceptable() ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
