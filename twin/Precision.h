#pragma once
// The twin's number types. Every value is held in double; the float and half twins round
// each result to the format a device would store it in. For +, -, *, / and sqrt, double
// (53 bits) is wide enough that rounding its correctly rounded result again to binary32 or
// binary16 gives the correctly rounded result of that format, so these twins are ideal
// IEEE devices; transcendentals are double results rounded once (better than any GPU).
#include <cmath>
#include <string>

namespace twin {

enum class Precision {
  exact,    // double: the default twin
  single,   // every float operation rounded to IEEE binary32
  half,     // RelaxedPrecision operations rounded to binary16, the others to binary32
};

const char* to_string(Precision);   // "double", "float", "half"
bool parse_precision(const std::string& text, Precision& out);

inline double round_to_float(double x) { return double(float(x)); }

// Round to nearest even at binary16's precision: 11 significant bits, subnormals down to
// 2^-24, overflow to infinity at 65520 (halfway between 65504 and 2^16).
inline double round_to_half(double x) {
  if (!std::isfinite(x) || x == 0) return x;
  const double a = std::fabs(x);
  if (a >= 65520.0) return std::copysign(INFINITY, x);
  int exponent = 0;
  std::frexp(a, &exponent);   // a = m * 2^exponent, m in [0.5, 1)
  const double quantum = exponent - 1 >= -14 ? std::ldexp(1.0, exponent - 11) : std::ldexp(1.0, -24);
  return std::copysign(std::nearbyint(a / quantum) * quantum, x);
}

}  // namespace twin
