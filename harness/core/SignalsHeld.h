#pragma once
// SIGINT, SIGTERM and SIGHUP held back (blocked, then delivered) for a scope that must not
// stop half-way: a stored set being replaced, or a finished run writing its reports.
#include <signal.h>

namespace shaderbed {

class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, s);
    ::pthread_sigmask(SIG_BLOCK, &held, &old_);
  }
  ~SignalsHeld() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t old_{};
};

}  // namespace shaderbed
