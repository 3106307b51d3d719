#pragma once
// A subcommand registers its options on the CLI11 app and returns the function that runs
// it once parsing is done. Exit status: 0 success, 1 a cell failed or could not run,
// 2 bad input.
#include <functional>

#include <CLI/CLI.hpp>

namespace shaderbed {

constexpr int kExitFail = 1;
constexpr int kExitBadInput = 2;

struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command add_run_command(CLI::App& app);
Command add_eval_command(CLI::App& app);
Command add_merge_command(CLI::App& app);
Command add_stats_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_hard_command(CLI::App& app);
Command add_bench_command(CLI::App& app);

}  // namespace shaderbed
