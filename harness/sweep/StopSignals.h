#pragma once
// SIGINT and SIGTERM, for as long as a StopSignals lives, only note that they came: a
// sweep asks between points and ends there with what it has (its JSON marked interrupted).
// The first signal restores the default action, so a second one ends the process at once
// (a point whose draw never ends can still be stopped from the keyboard).
#include <signal.h>

#include <string>

namespace shaderbed {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal caught so far ("SIGINT", "SIGTERM"), or "".
  std::string caught() const;
  // 130 after SIGINT, 143 after SIGTERM (the shell's 128 + signal), else 0.
  int exit_status() const;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace shaderbed
