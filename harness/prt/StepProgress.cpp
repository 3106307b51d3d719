#include "prt/StepProgress.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace shaderbed {

StepProgress::StepProgress(std::string what) : what_(std::move(what)), terminal_(isatty(STDERR_FILENO) != 0) {}

void StepProgress::update(size_t done, size_t total) {
  std::lock_guard lock(mutex_);
  if (total == 0) return;
  const auto now = Clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (terminal_) {
    if (done < total && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    drawn_ = true;
    fmt::print(stderr, "\r{}: {}/{} ({:.0f}%), {:.1f} s\033[K", what_, done, total, 100.0 * double(done) / double(total),
               seconds);
    return;
  }
  const size_t quarter = done * 4 / total;
  if (seconds >= 2.0 && quarter >= next_quarter_ && quarter < 4) {
    fmt::print(stderr, "{}: {}/{} ({}%), {:.1f} s\n", what_, done, total, quarter * 25, seconds);
    next_quarter_ = quarter + 1;
  }
}

void StepProgress::finish() {
  std::lock_guard lock(mutex_);
  if (drawn_) fmt::print(stderr, "\r\033[K");
  drawn_ = false;
}

}  // namespace shaderbed
