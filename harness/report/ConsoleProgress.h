#pragma once
// Progress of a run on stderr, fed by the runner's on_cell callback. On a terminal: one
// line refreshed in place, "[ 420/1400]  3.1 s  ETA 7.2 s  2 not passing", erased at the
// end. Otherwise (CI logs, pipes): a plain line at every tenth of the cells, so a log
// shows the run is alive without a line per cell.
#include <chrono>
#include <cstdio>
#include <string_view>

#include "report/Results.h"

namespace shaderbed {

class ConsoleProgress {
 public:
  // terminal: refresh one line (else print the tenths); quiet: print nothing off a terminal.
  ConsoleProgress(std::FILE* out, bool terminal, bool quiet = false);
  // Call once per finished cell, one call at a time (RunOptions::on_cell's guarantee).
  void update(size_t done, size_t total, const CellResult& cell);
  // The same display for work that is not cells (`stats`: a program compiled, a driver
  // read): `unit` names what is counted in the plain lines ("steps"), and on a terminal
  // `item` (what was just done, "phong/pixel/hlsl") follows the counts.
  void update(size_t done, size_t total, std::string_view unit, std::string_view item);

 private:
  void draw(size_t done, size_t total, std::string_view unit, std::string_view item);
  using Clock = std::chrono::steady_clock;
  std::FILE* out_;
  bool terminal_, quiet_;
  Clock::time_point start_, last_draw_;
  size_t not_passing_ = 0;
  size_t next_tenth_ = 1;   // the next tenth of the cells whose crossing prints a line
};

}  // namespace shaderbed
