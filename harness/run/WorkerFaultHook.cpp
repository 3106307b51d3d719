#include "run/WorkerFaultHook.h"

#include <signal.h>

#include <cstdlib>
#include <utility>

namespace shaderbed {
namespace {

int signal_named(const std::string& name) {
  for (const auto& [text, number] : {std::pair{"STOP", SIGSTOP}, std::pair{"KILL", SIGKILL}, std::pair{"SEGV", SIGSEGV},
                                     std::pair{"ABRT", SIGABRT}, std::pair{"TERM", SIGTERM}})
    if (name == text) return number;
  char* end = nullptr;
  const long number = std::strtol(name.c_str(), &end, 10);
  return !name.empty() && *end == '\0' && number > 0 && number < NSIG ? int(number) : 0;
}

}  // namespace

WorkerFaultHook WorkerFaultHook::from_environment() {
  WorkerFaultHook hook;
  const char* spec = std::getenv("SHADERBED_TEST_WORKER_FAULT");
  if (!spec) return hook;
  const std::string text = spec;
  const size_t at = text.find('@');
  if (at == std::string::npos) return hook;
  const size_t colon = text.find(':', at);
  std::string step = text.substr(at + 1, colon == std::string::npos ? std::string::npos : colon - at - 1);
  if (colon != std::string::npos) {
    std::string which = text.substr(colon + 1);
    const bool and_later = which.ends_with('+');
    if (and_later) which.pop_back();
    const char* mine = std::getenv("SHADERBED_WORKER_NUMBER");
    const long n = std::atol(which.c_str()), number = mine ? std::atol(mine) : 0;
    if (n <= 0 || number <= 0 || (and_later ? number < n : number != n)) return hook;
  }
  hook.signal_ = signal_named(text.substr(0, at));
  if (hook.signal_ != 0) hook.step_ = std::move(step);
  return hook;
}

void WorkerFaultHook::at(const std::string& step) const {
  if (signal_ != 0 && step == step_) ::raise(signal_);
}

}  // namespace shaderbed
