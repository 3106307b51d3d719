#include "run/WorkerProtocol.h"

#include <charconv>

#include "report/JsonReport.h"

namespace shaderbed {

Result<WorkerEvent> parse_worker_event(std::string_view line) {
  WorkerEvent e;
  const size_t space = line.find(' ');
  const std::string_view word = line.substr(0, space);
  const std::string_view rest = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
  if (word == "hello" || word == "cell") {
    auto report = parse_json(rest, "worker");
    if (!report) return std::unexpected(report.error());
    e.kind = word == "hello" ? WorkerEvent::Kind::hello : WorkerEvent::Kind::cell;
    e.report = std::move(*report);
    if (e.kind == WorkerEvent::Kind::cell && e.report.results.size() != 1)
      return fail(ErrorStage::worker, "a cell message holds " + std::to_string(e.report.results.size()) + " results");
  } else if (word == "step") {
    const size_t last = rest.rfind(' ');
    if (last == std::string_view::npos) return fail(ErrorStage::worker, "a step message needs a cell and a step");
    e.kind = WorkerEvent::Kind::step;
    e.cell_id = std::string(rest.substr(0, last));
    e.step = std::string(rest.substr(last + 1));
  } else if (word == "done") {
    e.kind = WorkerEvent::Kind::done;
    size_t* counts[] = {&e.compiles.disk_hits, &e.compiles.compiles, &e.compiles.memory_hits};
    std::string_view numbers = rest;
    for (size_t* out : counts) {
      while (numbers.starts_with(' ')) numbers.remove_prefix(1);
      const auto [end, ec] = std::from_chars(numbers.data(), numbers.data() + numbers.size(), *out);
      if (ec != std::errc()) return fail(ErrorStage::worker, "a done message needs three counts");
      numbers.remove_prefix(size_t(end - numbers.data()));
    }
  }
  return e;
}

}  // namespace shaderbed
