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
Command add_devices_command(CLI::App& app);
Command add_init_command(CLI::App& app);
Command add_port_command(CLI::App& app);
Command add_explain_command(CLI::App& app);        // one pixel of a cell's shader, line by line
Command add_cell_worker_command(CLI::App& app);   // hidden: an isolated run's worker process
Command add_compile_stages_command(CLI::App& app);   // hidden: compile/IsolatedCompile.h's child process
Command add_view_command(CLI::App& app);
Command add_view_compile_command(CLI::App& app);  // hidden: the viewer's compile probe (ViewCommand.cpp)
Command add_sh_command(CLI::App& app);            // sh project|transfer|eval (ShCommand.cpp)
Command add_help_command(CLI::App& app);          // help [COMMAND]: that command's --help
Command add_completion_command(CLI::App& app);    // completion bash: a completion script

// --cache-dir, --no-driver-cache, --no-compile-cache on the root app, accepted after any
// subcommand too (CacheOptions.cpp). Call after adding the subcommands and before any
// other root option, so the settings apply before anything loads a driver.
void add_cache_options(CLI::App& app);
// --vulkan-device on the root app, also accepted after a subcommand (DevicesCommand.cpp).
void add_vulkan_device_option(CLI::App& app);
// --gl-platform osmesa|egl and --gl-device on the root app, also accepted after a
// subcommand (DevicesCommand.cpp).
void add_gl_platform_options(CLI::App& app);
// --version: shaderbed's version and the toolchain fingerprint, drivers started to read it.
void add_version_flag(CLI::App& app);

}  // namespace shaderbed
