// `shaderbed __compile-stages`: not for people. A command that compiles a user's shaders
// (init, port, stats, sweep, hard) starts this binary so, as a child process, to compile
// them where a glslang crash costs nothing but an error (compile/IsolatedCompile.h).
#include <sys/stat.h>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "compile/StageCompileServer.h"

namespace shaderbed {

Command add_compile_stages_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("__compile-stages", "");
  cmd->group("");   // hidden
  return {cmd, [] {
            constexpr int kSocket = 3;   // where IsolatedCompile.cpp puts it
            struct stat s {};
            if (::fstat(kSocket, &s) != 0 || !S_ISSOCK(s.st_mode)) {
              fmt::print(stderr, "shaderbed: __compile-stages is started by shaderbed's other commands, not by hand\n");
              return kExitBadInput;
            }
            return serve_stage_compiles(kSocket);
          }};
}

}  // namespace shaderbed
