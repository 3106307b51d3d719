#pragma once
// The number type that checks the double twin: Boost.Multiprecision's quad (a 113-bit
// significand, 60 bits more than double), in software. Code instantiated for it calls the
// math functions unqualified, so a name found by `using std::...` for double finds Boost's
// overload for this type.
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace twin {

using WideReal = boost::multiprecision::cpp_bin_float_quad;

}  // namespace twin
