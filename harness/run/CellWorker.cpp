#include "run/CellWorker.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <exception>
#include <new>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "report/JsonReport.h"
#include "run/GroupRunner.h"
#include "run/Runner.h"
#include "run/Toolchain.h"
#include "run/WorkerFaultHook.h"
#include "run/WorkerOptions.h"
#include "run/WorkerProtocol.h"
#include "scene/NameFilter.h"

namespace shaderbed {
namespace {

// One line, whole: the supervisor reads lines, and a short write would split one.
void send(int fd, const std::string& line) {
  std::string text = line + "\n";
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(3);   // the supervisor is gone: nothing left to do
    p += n;
    left -= size_t(n);
  }
}

bool read_line(std::FILE* in, std::string& line) {
  line.clear();
  for (int ch; (ch = std::fgetc(in)) != EOF;) {
    if (ch == '\n') return true;
    line.push_back(char(ch));
  }
  return !line.empty();
}

// An allocation that fails past the worker's address-space limit ends it with an exit
// status the supervisor names "out of memory", not a crash of whatever step was running;
// also when it escapes through a noexcept frame or a library's thread into terminate().
[[noreturn]] void out_of_memory_or_abort() {
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      _exit(kWorkerOutOfMemoryExit);
    } catch (...) {
    }
  }
  std::abort();
}

int serve_cells_unguarded(std::FILE* commands, int events_fd);

}  // namespace

int serve_cells(std::FILE* commands, int events_fd) {
  std::set_terminate(out_of_memory_or_abort);
  try {
    return serve_cells_unguarded(commands, events_fd);
  } catch (const std::bad_alloc&) {
    _exit(kWorkerOutOfMemoryExit);   // no allocation here: the supervisor reads the status
  }
}

namespace {

int serve_cells_unguarded(std::FILE* commands, int events_fd) {
  const WorkerFaultHook fault = WorkerFaultHook::from_environment();
  std::string line;
  if (!read_line(commands, line)) return 2;
  auto decoded = decode_worker_options(line);
  if (!decoded) {
    fmt::print(stderr, "shaderbed worker: {}\n", decoded.error().to_string());
    return 2;
  }
  apply_process_settings(decoded->process);
  const RunOptions options{.select = decoded->select, .cell = decoded->cell, .workers = {.jobs = 1}};
  auto plan = plan_suite(options);
  if (!plan) {
    fmt::print(stderr, "shaderbed worker: {}\n", plan.error().to_string());
    return 2;
  }
  std::vector<BackendSlot> backends = start_backends((*plan)->backend_names);
  RunReport hello;
  hello.tools = toolchain(backends);
  fault.at("start");
  send(events_fd, "hello " + to_json_line(hello));
  auto stored = load_stored_references(options.cell.against_dir, options.cell.size, (*plan)->cases, hello.tools);
  if (!stored) {
    fmt::print(stderr, "shaderbed worker: {}\n", stored.error().to_string());
    return 2;
  }
  SceneSetup scene;
  scene.width = scene.height = options.cell.size;
  GroupRunner runner(options.cell, scene, *stored, wanted((*plan)->backend_names, "gl"),
                     [events_fd, &fault](const std::string& cell, const char* step) {
                       send(events_fd, fmt::format("step {} {}", cell, step));
                       fault.at(step);
                     });
  const CompileCacheCounts before = compile_cache_counts();

  // "group INDEX [SKIPPED-CELL-ID...]": the cells already settled by the supervisor (a
  // crash or a timeout) are left out.
  while (read_line(commands, line)) {
    std::istringstream words(line);
    std::string verb;
    size_t index = 0;
    if (!(words >> verb >> index) || verb != "group" || index >= (*plan)->groups.size()) return 2;
    std::set<std::string> skipped;
    for (std::string id; words >> id;) skipped.insert(id);
    CellGroup group = on_backends((*plan)->groups[index], **plan, backends);
    std::erase_if(group.cells, [&](const PlannedCell& cell) { return skipped.contains(cell_id(group, cell)); });
    if (!group.cells.empty())
      for (CellResult& r : runner.run(group)) {
        RunReport one;
        one.results.push_back(std::move(r));
        send(events_fd, "cell " + to_json_line(one));
      }
    const CompileCacheCounts counts = compile_cache_counts() - before;
    send(events_fd, fmt::format("done {} {} {}", counts.disk_hits, counts.compiles, counts.memory_hits));
  }
  return 0;
}

}  // namespace

}  // namespace shaderbed
