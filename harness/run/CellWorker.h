#pragma once
// The worker side of an isolated run (run/IsolatedRun.h, protocol in run/WorkerProtocol.h):
// a child process that reads the run's options and then group commands from `commands`,
// runs each group on backends of its own, and writes events to `events_fd`. Everything
// untrusted in a cell (compiling its shaders, drawing it) happens here, so a crash ends
// this process and not the run.
#include <cstdio>

namespace shaderbed {

// The exit status: 0 after the commands end; 2 when the options cannot be planned (the
// supervisor planned the same options, so that means the files changed underneath it).
int serve_cells(std::FILE* commands, int events_fd);

}  // namespace shaderbed
