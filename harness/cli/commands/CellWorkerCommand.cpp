// `shaderbed __cell-worker`: not for people. An isolated run (run/IsolatedRun.h) starts
// this binary so, as a child process, to compile and draw its cells; hidden from --help.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "run/CellWorker.h"

namespace shaderbed {

Command add_cell_worker_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("__cell-worker", "");
  cmd->group("");   // hidden
  return {cmd, [] {
            const char* fd = std::getenv("SHADERBED_WORKER_EVENTS_FD");
            if (!fd) {
              fmt::print(stderr, "shaderbed: __cell-worker is started by `shaderbed run`, not by hand\n");
              return kExitBadInput;
            }
            return serve_cells(stdin, std::atoi(fd));
          }};
}

}  // namespace shaderbed
