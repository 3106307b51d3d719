#include "run/CellWorker.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "report/JsonReport.h"
#include "run/GroupRunner.h"
#include "run/Runner.h"
#include "run/Toolchain.h"
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

}  // namespace

int serve_cells(std::FILE* commands, int events_fd) {
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
  send(events_fd, "hello " + to_json_line(hello));
  auto stored = load_stored_references(options.cell.against_dir, options.cell.size, (*plan)->cases, hello.tools);
  if (!stored) {
    fmt::print(stderr, "shaderbed worker: {}\n", stored.error().to_string());
    return 2;
  }
  SceneSetup scene;
  scene.width = scene.height = options.cell.size;
  GroupRunner runner(options.cell, scene, *stored, wanted((*plan)->backend_names, "gl"),
                     [events_fd](const std::string& cell, const char* step) {
                       send(events_fd, fmt::format("step {} {}", cell, step));
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

}  // namespace shaderbed
