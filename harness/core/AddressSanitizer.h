#pragma once
// Whether this build runs under AddressSanitizer (scripts/test --sanitize, the fuzz build):
// the few places that behave differently there ask this one constant.
#include <string>
#include <vector>

namespace shaderbed {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool address_sanitizer_build = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool address_sanitizer_build = true;
#else
inline constexpr bool address_sanitizer_build = false;
#endif
#else
inline constexpr bool address_sanitizer_build = false;
#endif

// This process's environment ("NAME=value" each) for a child whose crash the parent reports
// by its signal (cell workers, the viewer's compile probe). Under ASan it adds
// handle_segv=0: ASan's own SEGV handler would turn a crash in glslang into exit status 1,
// and the report would lose the signal.
std::vector<std::string> environment_keeping_crash_signals();

}  // namespace shaderbed
