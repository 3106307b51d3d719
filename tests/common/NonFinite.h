#pragma once
// The non-finite doubles the tests feed in, where NaN and infinity must be handled.
#include <limits>

namespace shaderbed::test {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace shaderbed::test
