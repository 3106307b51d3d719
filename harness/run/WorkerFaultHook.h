#pragma once
// A test's way to make an isolated worker fail at a chosen step, so the supervisor's
// handling of a worker that stops, crashes or is killed mid-step is tested at a
// deterministic point rather than at a random time:
//   SHADERBED_TEST_WORKER_FAULT="SIGNAL@STEP[:N[+]]"
// raises SIGNAL (STOP, KILL, SEGV, ABRT, or a number) in the worker numbered N (N+: N and
// every later one; no N: every worker) when it reaches STEP ("start" before its hello, or
// a step it announces: reference, compile, draw, judge, write, ...). The supervisor numbers
// its workers from 1 in SHADERBED_WORKER_NUMBER. Unset, it does nothing.
#include <string>

namespace shaderbed {

class WorkerFaultHook {
 public:
  // From this process's environment; inactive when unset or malformed.
  static WorkerFaultHook from_environment();

  // Raises the signal when `step` is the one named (after the step was announced).
  void at(const std::string& step) const;

 private:
  int signal_ = 0;
  std::string step_;
};

}  // namespace shaderbed
