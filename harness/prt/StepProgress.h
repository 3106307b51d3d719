#pragma once
// Progress of one long CPU step of `shaderbed sh` (a transfer, an exact integral) on
// stderr. On a terminal: one line refreshed in place (at most ten times a second) and
// erased at the end. Otherwise: nothing for the first two seconds, then a line at each
// quarter, so at most three lines in a log. Thread-safe. (The run engine's
// report/ConsoleProgress counts cells and their verdicts; a step has neither.)
#include <chrono>
#include <mutex>
#include <string>

#include "sh/Transfer.h"

namespace shaderbed {

class StepProgress {
 public:
  explicit StepProgress(std::string what);   // what: "sh eval: transfer", the line's start
  ~StepProgress() { finish(); }
  StepProgress(const StepProgress&) = delete;
  StepProgress& operator=(const StepProgress&) = delete;

  void update(size_t done, size_t total);
  // Erases the terminal line; later updates draw it again.
  void finish();
  // update() as the transfer's progress callback; valid while this lives.
  sh::TransferProgress callback() {
    return [this](size_t done, size_t total) { update(done, total); };
  }

 private:
  using Clock = std::chrono::steady_clock;
  std::string what_;
  bool terminal_;
  Clock::time_point start_ = Clock::now(), last_draw_ = start_;
  bool drawn_ = false;
  size_t next_quarter_ = 1;
  std::mutex mutex_;
};

}  // namespace shaderbed
