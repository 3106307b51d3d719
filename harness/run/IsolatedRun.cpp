#include "run/IsolatedRun.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <map>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "core/AddressSanitizer.h"
#include "core/Elapsed.h"
#include "run/WorkerOptions.h"
#include "run/WorkerProtocol.h"

namespace shaderbed {
namespace {


// ---- signals: SIGINT, SIGTERM and SIGHUP end the run with what it has -------------------

int signal_pipe[2] = {-1, -1};
volatile sig_atomic_t caught_signal = 0;

void on_signal(int signal) {
  if (caught_signal == 0) caught_signal = signal;   // the first one is what stopped the run
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(signal_pipe[1], &byte, 1);
}

// Catches SIGINT, SIGTERM and SIGHUP into a pipe poll() watches, and ignores SIGPIPE (a
// worker that died is noticed on its events pipe, not by a signal to us). Restores them
// after, except once a signal ended the run: then repeats (a second Ctrl-C, a terminal
// closing after it) are ignored, so the partial report is written before the process ends.
class SignalGuard {
 public:
  SignalGuard() {
    caught_signal = 0;
    if (::pipe2(signal_pipe, O_CLOEXEC | O_NONBLOCK) != 0) signal_pipe[0] = signal_pipe[1] = -1;
    struct sigaction handler {};
    handler.sa_handler = on_signal;
    // Each handler blocks the others: signals pending together run one after another,
    // so the first sent is the one recorded.
    sigemptyset(&handler.sa_mask);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&handler.sa_mask, s);
    ::sigaction(SIGINT, &handler, &old_int_);
    ::sigaction(SIGTERM, &handler, &old_term_);
    ::sigaction(SIGHUP, &handler, &old_hup_);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &old_pipe_);
  }
  ~SignalGuard() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    const bool stopping = caught_signal != 0;
    ::sigaction(SIGINT, stopping ? &ignore : &old_int_, nullptr);
    ::sigaction(SIGTERM, stopping ? &ignore : &old_term_, nullptr);
    ::sigaction(SIGHUP, stopping ? &ignore : &old_hup_, nullptr);
    ::sigaction(SIGPIPE, &old_pipe_, nullptr);
    for (int& fd : signal_pipe)
      if (fd >= 0) ::close(fd), fd = -1;
  }
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {}, old_hup_ {}, old_pipe_ {};
};

std::string signal_text(int signal) {
  const char* name = sigabbrev_np(signal);
  return name ? fmt::format("signal {} (SIG{})", signal, name) : fmt::format("signal {}", signal);
}

// ---- one worker process -----------------------------------------------------------------

struct Worker {
  pid_t pid = -1;
  int commands = -1;   // the worker's stdin
  int events = -1;     // its events pipe
  std::string buffer;  // what has arrived of the current line
  bool greeted = false;
  std::optional<size_t> bundle;   // the bundle it works through
  size_t position = 0;            // the group of that bundle it runs (an index into the bundle)
  bool busy = false;              // a group command is out
  std::string step_cell, step;    // what it said it does
  Clock::time_point step_start;
  std::vector<CellResult> pending;   // the current group's results so far
  CompileCacheCounts counts;         // as it last reported them
  int start_failures = 0;            // workers before this one, in its slot, that ended before their hello
};

// How many workers in a row may end before their hello before a slot gives up: the cells
// it had left become errors and the run goes on.
constexpr int kStartTries = 3;
constexpr double kStartTimeoutFloor_s = 30;

// What a worker was doing in each step, for the cell's message.
std::string doing(const std::string& step) {
  static const std::map<std::string, std::string> words = {
      {"start", "starting"},          {"group", "setting up"},        {"reference", "preparing the reference of"},
      {"compile", "compiling"},       {"draw", "drawing"},            {"judge", "judging"},
      {"write", "writing the images of"}, {"twin", "running the twin of"}, {"divergence", "locating the divergence of"},
      {"attribution", "attributing the failures of"}};
  const auto it = words.find(step);
  return it != words.end() ? it->second : "running " + step + " for";
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

bool write_all(int fd, const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    left -= size_t(n);
  }
  return true;
}

// Starts `binary __cell-worker` with its limits, and sends it the options. The worker gets
// its own process group (a terminal's Ctrl-C reaches the supervisor only) and dies with us.
Result<Worker> spawn_worker(const RunOptions& o, const std::string& options_line, int number) {
  int commands[2], events[2];
  if (::pipe2(commands, O_CLOEXEC) != 0) return fail(ErrorStage::isolation, std::string("pipe: ") + std::strerror(errno));
  if (::pipe2(events, O_CLOEXEC) != 0) {
    ::close(commands[0]), ::close(commands[1]);
    return fail(ErrorStage::isolation, std::string("pipe: ") + std::strerror(errno));
  }
  // Everything the child needs is built before fork: only async-signal-safe calls after it.
  std::vector<std::string> env_text = environment_keeping_crash_signals();
  std::erase_if(env_text, [](const std::string& e) {
    return e.starts_with("SHADERBED_WORKER_EVENTS_FD=") || e.starts_with("SHADERBED_WORKER_NUMBER=");
  });
  env_text.emplace_back("SHADERBED_WORKER_EVENTS_FD=3");
  env_text.emplace_back("SHADERBED_WORKER_NUMBER=" + std::to_string(number));   // for WorkerFaultHook
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::string program = o.workers.worker_binary, verb = "__cell-worker";
  char* argv[] = {program.data(), verb.data(), nullptr};
  const rlim_t memory = rlim_t(o.workers.worker_memory_mb) << 20;
  const pid_t parent = ::getpid();

  const pid_t pid = ::fork();
  if (pid < 0) return fail(ErrorStage::isolation, std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) _exit(126);
    // AddressSanitizer reserves terabytes of shadow address space at start, so under it the
    // limit would stop every worker; its own allocator refuses absurd sizes instead.
    if constexpr (!address_sanitizer_build) {
      const rlimit as{memory, memory};
      ::setrlimit(RLIMIT_AS, &as);
    }
    // Deep recursion in a parser (10^5 nested parentheses) overflows this and crashes the
    // worker, which is what isolation is for; 64 MiB keeps ordinary shaders far from it.
    const rlimit stack{rlim_t(64) << 20, rlim_t(64) << 20};
    ::setrlimit(RLIMIT_STACK, &stack);
    ::dup2(commands[0], 0);
    ::dup2(events[1], 3);
    ::execve(program.c_str(), argv, envp.data());
    _exit(127);
  }
  ::close(commands[0]);
  ::close(events[1]);
  ::fcntl(events[0], F_SETFL, O_NONBLOCK);
  // Start-up (drivers, the plan, stored images) is a step with a deadline like any other.
  Worker w{.pid = pid, .commands = commands[1], .events = events[0], .step = "start", .step_start = Clock::now()};
  if (!write_all(w.commands, options_line + "\n")) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    close_fd(w.commands), close_fd(w.events);
    return fail(ErrorStage::isolation, "the worker did not take its options");
  }
  return w;
}

// Kills (if still alive) and reaps; how it ended: "signal 11 (SIGSEGV)", "exit 3".
std::string end_worker(Worker& w, bool kill_it) {
  if (kill_it) ::kill(w.pid, SIGKILL);
  int status = 0;
  while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
  }
  close_fd(w.commands), close_fd(w.events);
  w.pid = -1;
  if (WIFSIGNALED(status))
    return signal_text(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGKILL && !kill_it ? ", sent by another process or the system's out-of-memory killer" : "");
  return fmt::format("exit {}", WEXITSTATUS(status));
}

bool out_of_memory(const std::string& how) { return how == fmt::format("exit {}", kWorkerOutOfMemoryExit); }

// ---- the supervisor -------------------------------------------------------------------

class Supervisor {
 public:
  Supervisor(const RunOptions& o, const SuitePlan& plan)
      : o_(o), plan_(plan), bundles_(bundles_of(plan.groups)), options_line_(encode_worker_options(worker_options(o))) {
    for (size_t b = 0; b < bundles_.size(); ++b) queue_.push_back(b);
  }

  Result<IsolatedResults> run() {
    SignalGuard signals;
    const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
    const size_t count = std::min(bundles_.size(), size_t(o_.workers.jobs > 0 ? o_.workers.jobs : hardware));
    for (size_t i = 0; i < count; ++i) {
      auto w = spawn_worker(o_, options_line_, out_.workers + 1);
      if (!w) return std::unexpected(w.error());
      workers_.push_back(std::move(*w));
      ++out_.workers;
    }
    while (!finished()) {
      if (caught_signal) return interrupted();
      std::vector<pollfd> fds;
      for (const Worker& w : workers_) fds.push_back({w.events, POLLIN, 0});
      fds.push_back({signal_pipe[0], POLLIN, 0});
      const int ready = ::poll(fds.data(), nfds_t(fds.size()), poll_timeout_ms());
      if (ready < 0 && errno != EINTR) return fail(ErrorStage::isolation, std::string("poll: ") + std::strerror(errno));
      if (caught_signal) return interrupted();
      for (size_t i = 0; i < workers_.size(); ++i) {
        if (fds[i].revents == 0) continue;
        if (auto ok = read_events(workers_[i]); !ok) return std::unexpected(ok.error());
      }
      if (auto ok = check_timeouts(); !ok) return std::unexpected(ok.error());
    }
    for (Worker& w : workers_)
      if (w.pid > 0) {
        close_fd(w.commands);   // end of commands: the worker exits
        end_worker(w, false);
      }
    for (const Worker& w : workers_) out_.compiles = out_.compiles + w.counts;
    out_.compiles = out_.compiles + retired_counts_;
    return std::move(out_);
  }

 private:
  bool finished() const {
    if (!queue_.empty()) return false;
    for (const Worker& w : workers_)
      if (w.bundle) return false;
    return true;
  }

  // The earliest step deadline, so a hung step is noticed on time.
  int poll_timeout_ms() const {
    double wait = 1000;
    const auto now = Clock::now();
    for (const Worker& w : workers_) {
      const double limit = step_limit_s(w.step);
      if (limit <= 0 || w.pid < 0) continue;
      const double elapsed = std::chrono::duration<double>(now - w.step_start).count();
      wait = std::min(wait, std::max(0.0, (limit - elapsed) * 1000 + 5));
    }
    return int(wait);
  }

  // Every step has a deadline: a worker that stops anywhere (SIGSTOP, a livelock in a
  // driver, a CPU reference that never ends) costs its cell, never the run.
  double step_limit_s(const std::string& step) const {
    if (step.empty()) return 0;   // idle: no group sent
    if (step == "compile") return o_.workers.compile_timeout_s;
    if (step == "draw") return o_.workers.draw_timeout_s;
    // Loading the drivers takes seconds on a busy machine: a --step-timeout short enough
    // for judging a small image must not kill every start-up.
    if (step == "start") return std::max(step_timeout_s(), kStartTimeoutFloor_s);
    return step_timeout_s();
  }

  double step_timeout_s() const {
    return o_.workers.step_timeout_s > 0 ? o_.workers.step_timeout_s : step_timeout_for_size(o_.cell.size);
  }

  Result<void> check_timeouts() {
    const auto now = Clock::now();
    for (Worker& w : workers_) {
      const double limit = step_limit_s(w.step);
      if (limit <= 0 || w.pid < 0) continue;
      if (std::chrono::duration<double>(now - w.step_start).count() <= limit) continue;
      end_worker(w, true);
      if (w.step == "compile" || w.step == "draw") {
        lost(w, fmt::format("timeout: {} took longer than {:g} s (--{}-timeout)",
                            w.step == "compile" ? "compiling its shaders" : "the draw", limit, w.step));
        continue;
      }
      const std::string how = fmt::format("timeout in {}: the step took longer than {:g} s (--step-timeout)", w.step, limit);
      if (!w.greeted)
        failed_start(w, how);
      else
        lost(w, how);
    }
    return {};
  }

  Result<void> read_events(Worker& w) {
    char chunk[65536];
    for (;;) {
      const ssize_t n = ::read(w.events, chunk, sizeof chunk);
      if (n > 0) {
        w.buffer.append(chunk, size_t(n));
        size_t newline;
        while ((newline = w.buffer.find('\n')) != std::string::npos) {
          const std::string line = w.buffer.substr(0, newline);
          w.buffer.erase(0, newline + 1);
          if (auto ok = handle(w, line); !ok) return ok;
        }
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EINTR)) return {};
      // End of the pipe: the worker is gone.
      const std::string how = end_worker(w, false);
      if (!w.greeted) {
        failed_start(w, how);
        return {};
      }
      if (out_of_memory(how))
        lost(w, fmt::format("out of memory: the worker's allocations passed its {} MiB limit (--worker-memory)",
                            o_.workers.worker_memory_mb));
      else
        lost(w, w.step == "compile" ? "compiler crashed: " + how : "crashed: " + how);
      return {};
    }
  }

  Result<void> handle(Worker& w, const std::string& line) {
    auto event = parse_worker_event(line);
    if (!event) return std::unexpected(event.error());
    switch (event->kind) {
      case WorkerEvent::Kind::hello:
        w.greeted = true;
        w.start_failures = 0;
        w.step.clear();
        if (out_.tools.glslang.empty()) out_.tools = event->report.tools;
        next_group(w);
        break;
      case WorkerEvent::Kind::step:
        w.step_cell = event->cell_id;
        w.step = event->step;
        w.step_start = Clock::now();
        break;
      case WorkerEvent::Kind::cell:
        w.pending.push_back(std::move(event->report.results.front()));
        break;
      case WorkerEvent::Kind::done:
        w.counts = event->compiles;
        finish_group(w);
        ++w.position;
        next_group(w);
        break;
      case WorkerEvent::Kind::unknown:
        break;
    }
    return {};
  }

  // The group's results, the supervisor's own (crashes, timeouts) with the worker's.
  void finish_group(Worker& w) {
    const size_t g = bundles_[*w.bundle][w.position];
    std::vector<CellResult> results = std::move(w.pending);
    w.pending.clear();
    for (CellResult& r : settled_[g]) results.push_back(std::move(r));
    settled_.erase(g);
    for (CellResult& r : results) {
      out_.results.push_back(std::move(r));
      if (o_.on_cell) o_.on_cell(out_.results.size(), plan_.cells, out_.results.back());
    }
    w.busy = false;
    w.step.clear();
    w.step_cell.clear();
  }

  // Sends the worker its next group: the next of its bundle, or the first of the next bundle.
  void next_group(Worker& w) {
    for (;;) {
      if (w.bundle && w.position >= bundles_[*w.bundle].size()) w.bundle.reset();
      if (!w.bundle) {
        if (queue_.empty()) return;
        w.bundle = queue_.front();
        queue_.pop_front();
        w.position = 0;
      }
      const size_t g = bundles_[*w.bundle][w.position];
      const CellGroup& group = plan_.groups[g];
      // Cells whose program crashed the compiler in an earlier group are settled at once.
      std::string command = fmt::format("group {}", g);
      size_t left = 0;
      for (const PlannedCell& cell : group.cells) {
        const std::string id = cell_id(group, cell);
        if (!is_settled(g, id) && crashed_programs_.contains(program_key(group, cell)))
          settle(g, group, cell, crashed_programs_.at(program_key(group, cell)));
        if (is_settled(g, id)) command += " " + id;
        else ++left;
      }
      if (left == 0) {   // nothing for the worker to do in this group
        w.busy = true;
        finish_group(w);
        ++w.position;
        continue;
      }
      if (!write_all(w.commands, command + "\n")) return;   // it died: its events pipe says so
      w.busy = true;
      // Until the worker names its first step (the group's LUT and mesh, stored images).
      w.step = "group";
      w.step_cell = group.c->name + "/" + group.variant->name + "/" + group.shape;
      w.step_start = Clock::now();
      return;
    }
  }

  static std::string program_key(const CellGroup& g, const PlannedCell& cell) {
    return g.c->name + "/" + g.variant->name + "/" + to_string(cell.language);
  }

  bool is_settled(size_t g, const std::string& id) const {
    const auto it = settled_.find(g);
    return it != settled_.end() &&
           std::ranges::any_of(it->second, [&](const CellResult& r) { return r.id() == id; });
  }

  void settle(size_t g, const CellGroup& group, const PlannedCell& cell, const std::string& message) {
    CellResult r{.case_name = group.c->name, .variant = group.variant->name, .language = to_string(cell.language),
                 .backend = cell.backend->name, .path = to_string(cell.path), .shape = group.shape};
    r.status = CellStatus::error;
    r.message = message;
    settled_[g].push_back(std::move(r));
  }

  // The worker crashed or was killed: the cell it named last is settled as an error (with
  // every cell of its program, when it was compiling), and a new worker takes the group up.
  void lost(Worker& w, const std::string& how) {
    retired_counts_ = retired_counts_ + w.counts;
    w.counts = {};
    if (w.bundle && w.busy) {
      const size_t g = bundles_[*w.bundle][w.position];
      const CellGroup& group = plan_.groups[g];
      w.pending.clear();
      const auto named = std::ranges::find_if(group.cells, [&](const PlannedCell& c) { return cell_id(group, c) == w.step_cell; });
      const bool fresh = named != group.cells.end() && !is_settled(g, w.step_cell);
      if (fresh && w.step == "compile") {
        const Case& c = *group.c;
        const ShaderFiles& files = group.variant->shaders.at(named->language);
        const std::string message = fmt::format(
            "{} while compiling {}'s {} shaders ({}{}) [stage compile]: the cells of this program are not drawn", how,
            c.name, to_string(named->language), files.vertex, files.vertex == files.fragment ? "" : ", " + files.fragment);
        crashed_programs_[program_key(group, *named)] = message;
        for (const PlannedCell& cell : group.cells)
          if (program_key(group, cell) == program_key(group, *named) && !is_settled(g, cell_id(group, cell)))
            settle(g, group, cell, message);
      } else if (fresh) {
        settle(g, group, *named, fmt::format("{} while {} this cell [stage {}]", how, doing(w.step),
                                             w.step.empty() ? "worker" : w.step));
      } else {
        // Not one of the group's own cells (the original drawn as its reference, a
        // counterfactual, the group as a whole), or one already settled: the group cannot
        // be run.
        for (const PlannedCell& cell : group.cells)
          if (!is_settled(g, cell_id(group, cell)))
            settle(g, group, cell, fmt::format("{} while {} {} [stage {}]: this cell's group could not be run", how,
                                               doing(w.step), w.step_cell.empty() ? "its reference" : w.step_cell,
                                               w.step.empty() ? "worker" : w.step));
      }
    }
    // A new worker picks the bundle up where it stopped.
    const std::optional<size_t> bundle = w.bundle;
    const size_t position = w.position;
    auto replacement = spawn_worker(o_, options_line_, out_.workers + 1);
    if (!replacement) {
      give_up(w, bundle, position, "worker could not be started: " + replacement.error().to_string());
      return;
    }
    ++out_.workers;
    w = std::move(*replacement);
    w.bundle = bundle;
    w.position = position;
  }

  // A worker ended before its hello: another is started in its place, a few times; then
  // the slot gives up and the cells it had left (every queued one, when no slot is left)
  // become errors, and the run writes its report even when no worker ever started.
  void failed_start(Worker& w, std::string how) {
    retired_counts_ = retired_counts_ + w.counts;
    const std::optional<size_t> bundle = w.bundle;
    const size_t position = w.position;
    const int failures = w.start_failures + 1;
    if (failures < kStartTries) {
      auto replacement = spawn_worker(o_, options_line_, out_.workers + 1);
      if (replacement) {
        ++out_.workers;
        w = std::move(*replacement);
        w.bundle = bundle;
        w.position = position;
        w.start_failures = failures;
        return;
      }
      how = replacement.error().to_string();
    }
    const std::string message = fmt::format("worker could not be started: {} ({} tr{})", how, failures,
                                            failures == 1 ? "y" : "ies");
    const bool last_slot = std::ranges::none_of(workers_, [&](const Worker& other) { return &other != &w && other.pid > 0; });
    give_up(w, bundle, position, message);
    if (last_slot)
      while (!queue_.empty()) {
        const size_t next = queue_.front();
        queue_.pop_front();
        give_up(w, next, 0, message);
      }
  }

  // Without a worker the rest of `bundle` from `position` cannot run: its cells become
  // errors saying why, and the slot is left empty.
  void give_up(Worker& w, std::optional<size_t> bundle, size_t position, const std::string& message) {
    if (bundle)
      for (size_t p = position; p < bundles_[*bundle].size(); ++p) {
        const size_t g = bundles_[*bundle][p];
        for (const PlannedCell& cell : plan_.groups[g].cells)
          if (!is_settled(g, cell_id(plan_.groups[g], cell))) settle(g, plan_.groups[g], cell, message);
        w.bundle = bundle, w.position = p, w.busy = true;
        finish_group(w);
      }
    w = Worker{};
  }

  Result<IsolatedResults> interrupted() {
    for (Worker& w : workers_)
      if (w.pid > 0) end_worker(w, true);
    const int signal = caught_signal;
    const char* name = sigabbrev_np(signal);
    out_.interruption = Interruption{
        signal, fmt::format("interrupted by SIG{} after {} of {} cells", name ? name : "INT", out_.results.size(), plan_.cells)};
    for (const Worker& w : workers_) out_.compiles = out_.compiles + w.counts;
    out_.compiles = out_.compiles + retired_counts_;
    return std::move(out_);
  }

  const RunOptions& o_;
  const SuitePlan& plan_;
  const std::vector<std::vector<size_t>> bundles_;
  const std::string options_line_;
  std::deque<size_t> queue_;                           // bundles no worker has taken
  std::vector<Worker> workers_;
  std::map<size_t, std::vector<CellResult>> settled_;  // by group: cells the supervisor decided
  std::map<std::string, std::string> crashed_programs_;   // case/variant/language -> the message
  CompileCacheCounts retired_counts_;                  // of workers that are gone
  IsolatedResults out_;
};

}  // namespace

Result<IsolatedResults> run_isolated(const RunOptions& options, const SuitePlan& plan) {
  return Supervisor(options, plan).run();
}

}  // namespace shaderbed
