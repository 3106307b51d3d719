#include "core/AddressSanitizer.h"

#include <unistd.h>   // environ (glibc declares it with _GNU_SOURCE, which g++ and clang++ set)

#include <algorithm>

namespace shaderbed {

std::vector<std::string> environment_keeping_crash_signals() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) env.emplace_back(*e);
  if constexpr (address_sanitizer_build) {
    auto asan = std::find_if(env.begin(), env.end(), [](const std::string& e) { return e.starts_with("ASAN_OPTIONS="); });
    if (asan == env.end()) env.emplace_back("ASAN_OPTIONS=handle_segv=0");
    else *asan += ":handle_segv=0";
  }
  return env;
}

}  // namespace shaderbed
