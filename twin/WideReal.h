#pragma once
// The number type that checks the double twin: Boost.Multiprecision's quad (a 113-bit
// significand, 60 bits more than double), in software. Code instantiated for it calls the
// math functions unqualified, so a name found by `using std::...` for double finds Boost's
// overload for this type.
#include <cmath>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace twin {

using WideReal = boost::multiprecision::cpp_bin_float_quad;

// The executor's math, called unqualified: std's for double, Boost's (by argument-dependent
// lookup) for WideReal.
using std::sin;
using std::cos;
using std::tan;
using std::asin;
using std::acos;
using std::atan;
using std::sinh;
using std::cosh;
using std::tanh;
using std::asinh;
using std::acosh;
using std::atanh;
using std::atan2;
using std::pow;
using std::exp;
using std::log;
using std::exp2;
using std::log2;
using std::sqrt;
using std::fabs;
using std::floor;
using std::ceil;
using std::trunc;
using std::round;
using std::nearbyint;
using std::fmod;
using std::fmin;
using std::fmax;
using std::fma;
using std::ldexp;
using std::frexp;
using std::modf;
using std::isnan;
using std::isinf;
using std::isfinite;
using std::signbit;
using std::abs;
using std::copysign;

}  // namespace twin
