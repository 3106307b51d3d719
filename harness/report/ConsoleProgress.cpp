#include "report/ConsoleProgress.h"

#include <string>

#include <fmt/format.h>

namespace shaderbed {

ConsoleProgress::ConsoleProgress(std::FILE* out, bool terminal, bool quiet)
    : out_(out), terminal_(terminal), quiet_(quiet), start_(Clock::now()), last_draw_() {}

void ConsoleProgress::update(size_t done, size_t total, const CellResult& cell) {
  // Counted before the expectations are applied, so known failures are in it too.
  not_passing_ += cell.status != CellStatus::pass && cell.status != CellStatus::skipped;
  draw(done, total, "cells", "");
}

void ConsoleProgress::update(size_t done, size_t total, std::string_view unit, std::string_view item) {
  draw(done, total, unit, item);
}

void ConsoleProgress::draw(size_t done, size_t total, std::string_view unit, std::string_view item) {
  const Clock::time_point now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = done ? elapsed / double(done) * double(total - done) : 0;
  const std::string failing = not_passing_ ? fmt::format("  {} not passing", not_passing_) : "";
  if (terminal_) {
    // At most ~20 redraws a second: a fast run should not spend its time on the terminal.
    if (done < total && now - last_draw_ < std::chrono::milliseconds(50)) return;
    last_draw_ = now;
    const std::string line = fmt::format("[{:>4}/{}] {:6.1f} s  ETA {:5.1f} s{}{}{}", done, total, elapsed, eta, failing,
                                         item.empty() ? "" : "  ", item);
    fmt::print(out_, "\r{}\x1b[K", line);   // \x1b[K: clear what a longer earlier line left
    if (done == total) fmt::print(out_, "\r\x1b[K");
    std::fflush(out_);
    return;
  }
  if (quiet_ || total == 0 || done * 10 < next_tenth_ * total) return;
  while (done * 10 >= next_tenth_ * total) ++next_tenth_;   // a jump past several tenths prints once
  fmt::print(out_, "progress: {}/{} {} ({}%), {:.1f} s, ETA {:.1f} s{}\n", done, total, unit, done * 100 / total,
             elapsed, eta, failing);
  std::fflush(out_);
}

}  // namespace shaderbed
