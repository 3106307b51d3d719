#include "sweep/StopSignals.h"

namespace shaderbed {
namespace {

volatile sig_atomic_t caught_signal = 0;

void on_signal(int signal) { caught_signal = signal; }

}  // namespace

StopSignals::StopSignals() {
  caught_signal = 0;
  struct sigaction handler {};
  handler.sa_handler = on_signal;
  handler.sa_flags = SA_RESETHAND;   // the second signal takes its default action
  sigemptyset(&handler.sa_mask);
  ::sigaction(SIGINT, &handler, &old_int_);
  ::sigaction(SIGTERM, &handler, &old_term_);
}

StopSignals::~StopSignals() {
  ::sigaction(SIGINT, &old_int_, nullptr);
  ::sigaction(SIGTERM, &old_term_, nullptr);
}

std::string StopSignals::caught() const {
  const int s = caught_signal;
  return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "";
}

int StopSignals::exit_status() const {
  const int s = caught_signal;
  return s == 0 ? 0 : 128 + s;
}

}  // namespace shaderbed
