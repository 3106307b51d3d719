// `shaderbed merge A.json B.json ...`: joins shard results into one report, in the same
// canonical order as one whole run. A shard is a file anyone can edit: its cells are judged
// again (report/ShardMerge.h), and its artefact paths are confined to its own folder for
// the HTML page (report/ShardArtefacts.h).
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/commands/ColourChoice.h"
#include "cli/commands/Command.h"
#include "cli/commands/ReportOutputs.h"
#include "run/Runner.h"
#include "report/ConsoleReport.h"
#include "report/JsonReport.h"
#include "report/RunCoverage.h"
#include "report/ShardArtefacts.h"
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
            if (!args->outputs.load_charts() || !args->outputs.check_writable() ||
                !args->outputs.check_not_inputs(args->inputs))
              return kExitBadInput;
            std::vector<RunReport> parts;
            std::map<std::string, std::pair<std::string, std::string>> origin;   // cell id -> its file, its run folder
            for (const std::string& path : args->inputs) {
              auto part = read_json(path);
              if (!part) {
                fmt::print(stderr, "shaderbed: {}\n", part.error().to_string());
                return kExitBadInput;
              }
              for (const CellResult& r : part->results) origin.emplace(r.id(), std::pair{path, part->out_dir});
              parts.push_back(std::move(*part));
            }
            std::vector<std::string> rejudged;
            auto joined = merge_shards(std::move(parts), args->inputs, &rejudged);
            if (!joined) {
              fmt::print(stderr, "shaderbed: {}\n", joined.error().to_string());
              return kExitBadInput;
            }
            RunReport& merged = *joined;
            for (const std::string& line : rejudged) fmt::print(stderr, "shaderbed: {}\n", line);
            // The page reads and links only files inside each shard's own folder.
            std::optional<RunReport> page;
            std::vector<std::string> notes;
            if (!args->outputs.html.empty()) {
              page = merged;
              std::vector<std::string> dropped;
              for (CellResult& r : page->results) {
                const auto& [file, out_dir] = origin.at(r.id());
                for (std::string& d : confine_artefacts(r, file, out_dir)) dropped.push_back(std::move(d));
              }
              if (!dropped.empty())
                notes.push_back(fmt::format("{} artefact path{} not shown: outside the folder of the results file that "
                                            "names {}, e.g. {}",
                                            dropped.size(), dropped.size() == 1 ? "" : "s", dropped.size() == 1 ? "it" : "them",
                                            dropped.front()));
            }
            const RunCoverage coverage = run_coverage(merged);
            if (args->console.view != ConsoleView::quiet) fmt::print(args->outputs.console(), "merged {} file{}: {} cells of {} case{}\n", args->inputs.size(), args->inputs.size() == 1 ? "" : "s",
                       merged.results.size(), coverage.cases, coverage.cases == 1 ? "" : "s");
            if (args->console.view != ConsoleView::quiet)
              for (const std::string& line : coverage.lines) fmt::print(args->outputs.console(), "  {}\n", line);
            if (!coverage.holes.empty())
              fmt::print(args->outputs.console(), "  no cells for {}: was a job of the matrix left out?\n", fmt::join(coverage.holes, ", "));
            args->console.colour = colour_on(args->outputs.console());
            print_console_report(merged, args->outputs.console(), args->console);
            if (!args->outputs.write(merged, page ? &*page : nullptr, notes)) return kExitFail;
            return merged.acceptable() ? 0 : kExitFail;
          }};
}

}  // namespace shaderbed
