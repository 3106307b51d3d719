#pragma once
// Whether this build runs under AddressSanitizer (scripts/test --sanitize, the fuzz build):
// the few places that behave differently there ask this one constant.

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

}  // namespace shaderbed
