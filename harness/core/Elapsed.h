#pragma once
// Wall time since a moment, in milliseconds, on the monotonic clock every timing here uses.
#include <chrono>

namespace shaderbed {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace shaderbed
