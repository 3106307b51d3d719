// GLSL.std.450, the extended instructions glslang emits for every GLSL and HLSL built-in
// function. Compound functions (length, normalize, reflect, ...) are computed as a GPU
// lowers them, step by step, each step rounded in the float and half twins.
#include <spirv/unified1/GLSL.std.450.h>
#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "twin/Executor.h"

namespace twin {

namespace {

template <typename T>
T nan_value() { return std::numeric_limits<T>::quiet_NaN(); }

// GPUs compute pow as exp2(y * log2(x)): undefined (NaN) for x < 0.
template <typename T>
T gpu_pow(T x, T y) { return x < 0 ? nan_value<T>() : pow(x, y); }

template <typename T>
T determinant(std::vector<T> a, int n) {
  // Gaussian elimination with partial pivoting; column-major a[c * n + r].
  T det = 1;
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if (fabs(a[c * n + r]) > fabs(a[c * n + pivot])) pivot = r;
    if (a[c * n + pivot] == 0) return 0;
    if (pivot != c) {
      for (int k = 0; k < n; ++k) std::swap(a[k * n + c], a[k * n + pivot]);
      det = -det;
    }
    det *= a[c * n + c];
    for (int r = c + 1; r < n; ++r) {
      const T f = a[c * n + r] / a[c * n + c];
      for (int k = c; k < n; ++k) a[k * n + r] -= f * a[k * n + c];
    }
  }
  return det;
}

template <typename T>
std::vector<T> inverse(const std::vector<T>& m, int n) {
  // Gauss-Jordan on [M | I]; a singular matrix gives infinities/NaN as a GPU's would.
  std::vector<T> a(m), inv(size_t(n) * n, T(0));
  for (int i = 0; i < n; ++i) inv[i * n + i] = 1;
  auto at = [n](std::vector<T>& v, int r, int c) -> T& { return v[size_t(c) * n + r]; };
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if (fabs(at(a, r, c)) > fabs(at(a, pivot, c))) pivot = r;
    for (int k = 0; k < n; ++k) {
      std::swap(at(a, c, k), at(a, pivot, k));
      std::swap(at(inv, c, k), at(inv, pivot, k));
    }
    const T p = at(a, c, c);
    for (int k = 0; k < n; ++k) {
      at(a, c, k) /= p;
      at(inv, c, k) /= p;
    }
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      const T f = at(a, r, c);
      for (int k = 0; k < n; ++k) {
        at(a, r, k) -= f * at(a, c, k);
        at(inv, r, k) -= f * at(inv, c, k);
      }
    }
  }
  return inv;
}

}  // namespace

template <typename Real>
TwinResult<void> BasicExecutor<Real>::execute_ext(uint32_t index, const Lanes& lanes) {
  const Instruction& in = m_.instructions[index];
  const auto all = m_.operands_of(in);
  if (!m_.glsl_std450[all[0]])
    return std::unexpected(error(in, "the twin runs GLSL.std.450 extended instructions only"));
  const auto op = GLSLstd450(all[1]);
  const auto ops = all.subspan(2);
  const uint32_t L = lanes_;
  const Type& rt = m_.types[in.result_type];
  const uint32_t n = rt.slots;
  Real* d = dst(in.result);
  const auto R = [&](Real x) { return rounded(index, x); };
  auto arg = [&](size_t i) { return src(ops[i]); };
  auto scalar_arg = [&](size_t i) { return slots_of(ops[i]) == 1 && n > 1; };
  auto map1 = [&](auto f) {
    const Src a = arg(0);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = R(f(a.at(s, l)));
  };
  auto map2 = [&](auto f) {
    const Src a = arg(0), b = arg(1);
    const bool bs = scalar_arg(1);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = R(f(a.at(s, l), b.at(bs ? 0 : s, l)));
  };
  auto map3 = [&](auto f) {
    const Src a = arg(0), b = arg(1), c = arg(2);
    const bool bs = scalar_arg(1), cs = scalar_arg(2);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = R(f(a.at(s, l), b.at(bs ? 0 : s, l), c.at(cs ? 0 : s, l)));
  };
  auto integer = [&](auto f) {   // integer functions: exact, no rounding
    const Src a = arg(0);
    for (uint32_t s = 0; s < n; ++s)
      for (uint16_t l : lanes) d[s * L + l] = f(a.at(s, l));
  };
  auto dot = [&](const Src& a, const Src& b, uint32_t count, uint16_t l) {
    Real sum = R(a.at(0, l) * b.at(0, l));
    for (uint32_t s = 1; s < count; ++s) sum = R(sum + R(a.at(s, l) * b.at(s, l)));
    return sum;
  };

  switch (op) {
    case GLSLstd450Round: map1([](Real x) { return round(x); }); break;
    case GLSLstd450RoundEven: map1([](Real x) { return nearbyint(x); }); break;
    case GLSLstd450Trunc: map1([](Real x) { return trunc(x); }); break;
    case GLSLstd450FAbs: map1([](Real x) { return fabs(x); }); break;
    case GLSLstd450SAbs: integer([](Real x) { return fabs(x); }); break;
    case GLSLstd450FSign: case GLSLstd450SSign:
      map1([](Real x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : x; });
      break;
    case GLSLstd450Floor: map1([](Real x) { return floor(x); }); break;
    case GLSLstd450Ceil: map1([](Real x) { return ceil(x); }); break;
    case GLSLstd450Fract: {
      const Src a = arg(0);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = R(a.at(s, l) - floor(a.at(s, l)));
      break;
    }
    case GLSLstd450Radians: map1([](Real x) { return x * (Real(acos(Real(-1))) / 180.0); }); break;
    case GLSLstd450Degrees: map1([](Real x) { return x * (180.0 / Real(acos(Real(-1)))); }); break;
    case GLSLstd450Sin: map1([](Real x) { return sin(x); }); break;
    case GLSLstd450Cos: map1([](Real x) { return cos(x); }); break;
    case GLSLstd450Tan: map1([](Real x) { return tan(x); }); break;
    case GLSLstd450Asin: map1([](Real x) { return asin(x); }); break;
    case GLSLstd450Acos: map1([](Real x) { return acos(x); }); break;
    case GLSLstd450Atan: map1([](Real x) { return atan(x); }); break;
    case GLSLstd450Sinh: map1([](Real x) { return sinh(x); }); break;
    case GLSLstd450Cosh: map1([](Real x) { return cosh(x); }); break;
    case GLSLstd450Tanh: map1([](Real x) { return tanh(x); }); break;
    case GLSLstd450Asinh: map1([](Real x) { return asinh(x); }); break;
    case GLSLstd450Acosh: map1([](Real x) { return acosh(x); }); break;
    case GLSLstd450Atanh: map1([](Real x) { return atanh(x); }); break;
    case GLSLstd450Atan2: map2([](Real y, Real x) { return atan2(y, x); }); break;
    case GLSLstd450Pow: map2([](Real x, Real y) { return gpu_pow(x, y); }); break;
    case GLSLstd450Exp: map1([](Real x) { return exp(x); }); break;
    case GLSLstd450Log: map1([](Real x) { return log(x); }); break;
    case GLSLstd450Exp2: map1([](Real x) { return exp2(x); }); break;
    case GLSLstd450Log2: map1([](Real x) { return log2(x); }); break;
    case GLSLstd450Sqrt: map1([](Real x) { return sqrt(x); }); break;
    case GLSLstd450InverseSqrt: map1([](Real x) { return 1.0 / sqrt(x); }); break;
    case GLSLstd450FMin: case GLSLstd450NMin: map2([](Real x, Real y) { return fmin(x, y); }); break;
    case GLSLstd450FMax: case GLSLstd450NMax: map2([](Real x, Real y) { return fmax(x, y); }); break;
    case GLSLstd450UMin: case GLSLstd450SMin: map2([](Real x, Real y) { return std::min(x, y); }); break;
    case GLSLstd450UMax: case GLSLstd450SMax: map2([](Real x, Real y) { return std::max(x, y); }); break;
    case GLSLstd450FClamp: case GLSLstd450NClamp:
      map3([](Real x, Real lo, Real hi) { return fmin(fmax(x, lo), hi); });
      break;
    case GLSLstd450UClamp: case GLSLstd450SClamp:
      map3([](Real x, Real lo, Real hi) { return std::min(std::max(x, lo), hi); });
      break;
    case GLSLstd450FMix: {   // x + (y - x) * a, each step rounded
      const Src x = arg(0), y = arg(1), a = arg(2);
      const bool as = scalar_arg(2);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes)
          d[s * L + l] = R(x.at(s, l) + R(R(y.at(s, l) - x.at(s, l)) * a.at(as ? 0 : s, l)));
      break;
    }
    case GLSLstd450IMix: map3([](Real x, Real y, Real a) { return a != 0 ? y : x; }); break;
    case GLSLstd450Step: {
      const Src edge = arg(0), x = arg(1);
      const bool es = scalar_arg(0);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) d[s * L + l] = x.at(s, l) < edge.at(es ? 0 : s, l) ? 0.0 : 1.0;
      break;
    }
    case GLSLstd450SmoothStep: {   // t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2t)
      const Src e0 = arg(0), e1 = arg(1), x = arg(2);
      const bool s0 = scalar_arg(0), s1 = scalar_arg(1);
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          const Real a = e0.at(s0 ? 0 : s, l), b = e1.at(s1 ? 0 : s, l);
          const Real t = fmin(fmax(R(R(x.at(s, l) - a) / R(b - a)), 0.0), 1.0);
          d[s * L + l] = R(R(t * t) * R(3.0 - R(2.0 * t)));
        }
      break;
    }
    case GLSLstd450Fma: map3([](Real a, Real b, Real c) { return fma(a, b, c); }); break;
    case GLSLstd450Ldexp: map2([](Real x, Real e) { return ldexp(x, int(std::clamp<Real>(e, Real(-2000.0), Real(2000.0)))); }); break;
    case GLSLstd450Modf: case GLSLstd450Frexp: {
      // The second result goes through the pointer operand.
      const Src x = arg(0);
      const Pointer& p = pointers_[ops[1]];
      Memory& mem = memory_[p.variable];
      for (uint32_t s = 0; s < n; ++s)
        for (uint16_t l : lanes) {
          Real other = 0, first;
          if (op == GLSLstd450Modf) {
            first = R(modf(x.at(s, l), &other));
          } else {
            int e = 0;
            first = R(frexp(x.at(s, l), &e));
            other = e;
          }
          d[s * L + l] = first;
          const size_t at = (size_t(p.at(l)) + s) * L + l;
          if (!mem.shared && at < mem.slots.size()) mem.slots[at] = other;
        }
      break;
    }
    case GLSLstd450ModfStruct: case GLSLstd450FrexpStruct: {
      const Src x = arg(0);
      const uint32_t half = n / 2;
      for (uint32_t s = 0; s < half; ++s)
        for (uint16_t l : lanes) {
          Real other = 0, first;
          if (op == GLSLstd450ModfStruct) {
            first = modf(x.at(s, l), &other);
          } else {
            int e = 0;
            first = frexp(x.at(s, l), &e);
            other = e;
          }
          d[s * L + l] = rounded(index, first);
          d[(half + s) * L + l] = other;
        }
      break;
    }
    case GLSLstd450Length: case GLSLstd450Distance: {
      const Src a = arg(0);
      const uint32_t count = slots_of(ops[0]);
      for (uint16_t l : lanes) {
        Real sum = 0;
        for (uint32_t s = 0; s < count; ++s) {
          const Real v = op == GLSLstd450Distance ? R(a.at(s, l) - arg(1).at(s, l)) : a.at(s, l);
          sum = s == 0 ? R(v * v) : R(sum + R(v * v));
        }
        d[l] = R(sqrt(sum));
      }
      break;
    }
    case GLSLstd450Cross: {
      const Src a = arg(0), b = arg(1);
      for (uint16_t l : lanes) {
        d[0 * L + l] = R(R(a.at(1, l) * b.at(2, l)) - R(b.at(1, l) * a.at(2, l)));
        d[1 * L + l] = R(R(a.at(2, l) * b.at(0, l)) - R(b.at(2, l) * a.at(0, l)));
        d[2 * L + l] = R(R(a.at(0, l) * b.at(1, l)) - R(b.at(0, l) * a.at(1, l)));
      }
      break;
    }
    case GLSLstd450Normalize: {   // v * inversesqrt(dot(v, v)), as Mesa lowers it
      const Src a = arg(0);
      for (uint16_t l : lanes) {
        const Real scale = R(1.0 / sqrt(dot(a, a, n, l)));
        for (uint32_t s = 0; s < n; ++s) d[s * L + l] = R(a.at(s, l) * scale);
      }
      break;
    }
    case GLSLstd450FaceForward: {   // dot(Nref, I) < 0 ? N : -N
      const Src N = arg(0), I = arg(1), Nref = arg(2);
      for (uint16_t l : lanes) {
        const bool keep = dot(Nref, I, n, l) < 0;
        for (uint32_t s = 0; s < n; ++s) d[s * L + l] = keep ? N.at(s, l) : -N.at(s, l);
      }
      break;
    }
    case GLSLstd450Reflect: {   // I - 2 * dot(N, I) * N
      const Src I = arg(0), N = arg(1);
      for (uint16_t l : lanes) {
        const Real k = R(2.0 * dot(N, I, n, l));
        for (uint32_t s = 0; s < n; ++s) d[s * L + l] = R(I.at(s, l) - R(k * N.at(s, l)));
      }
      break;
    }
    case GLSLstd450Refract: {
      const Src I = arg(0), N = arg(1), eta_arg = arg(2);
      for (uint16_t l : lanes) {
        const Real eta = eta_arg.at(0, l);
        const Real ni = dot(N, I, n, l);
        const Real k = R(1.0 - R(R(eta * eta) * R(1.0 - R(ni * ni))));
        for (uint32_t s = 0; s < n; ++s)
          d[s * L + l] = k < 0 ? 0.0 : R(R(eta * I.at(s, l)) - R(R(R(eta * ni) + R(sqrt(k))) * N.at(s, l)));
      }
      break;
    }
    case GLSLstd450Determinant: case GLSLstd450MatrixInverse: {
      const Src a = arg(0);
      const int size = int(m_.types[m_.type_of[ops[0]]].count);
      std::vector<Real> matrix(size_t(size) * size);
      for (uint16_t l : lanes) {
        for (int s = 0; s < size * size; ++s) matrix[s] = a.at(uint32_t(s), l);
        if (op == GLSLstd450Determinant) {
          d[l] = R(determinant(matrix, size));
        } else {
          const std::vector<Real> inv = inverse(matrix, size);
          for (int s = 0; s < size * size; ++s) d[size_t(s) * L + l] = R(inv[s]);
        }
      }
      break;
    }
    case GLSLstd450FindILsb:
      integer([](Real x) { const auto v = uint32_t(int64_t(x)); return v == 0 ? -1.0 : Real(__builtin_ctz(v)); });
      break;
    case GLSLstd450FindUMsb:
      integer([](Real x) { const auto v = uint32_t(int64_t(x)); return v == 0 ? -1.0 : Real(31 - __builtin_clz(v)); });
      break;
    case GLSLstd450FindSMsb:
      integer([](Real x) {
        auto v = uint32_t(int32_t(int64_t(x)));
        if (int32_t(v) < 0) v = ~v;
        return v == 0 ? -1.0 : Real(31 - __builtin_clz(v));
      });
      break;
    case GLSLstd450PackHalf2x16: {
      const Src a = arg(0);
      auto half_bits = [](Real x) -> uint32_t {
        const Real h = Real(round_to_half(double(x)));
        if (isnan(h)) return 0x7e00;
        const uint32_t sign = signbit(h) ? 0x8000 : 0;
        const Real m = fabs(h);
        if (isinf(m)) return sign | 0x7c00;
        if (m == 0) return sign;
        int e = 0;
        const Real f = frexp(m, &e);   // m = f * 2^e, f in [0.5, 1)
        if (e - 1 < -14) return sign | uint32_t(ldexp(m, 24));   // subnormal
        return sign | uint32_t((e - 1 + 15) << 10) | (uint32_t(ldexp(f, 11)) & 0x3ff);
      };
      for (uint16_t l : lanes) d[l] = Real(half_bits(a.at(0, l)) | (half_bits(a.at(1, l)) << 16));
      break;
    }
    case GLSLstd450UnpackHalf2x16: {
      const Src a = arg(0);
      auto from_half = [](uint32_t h) {
        const int exponent = int((h >> 10) & 0x1f);
        const Real mantissa = Real(h & 0x3ff);
        const Real v = exponent == 0 ? ldexp(mantissa, -24)
                         : exponent == 31 ? (mantissa != 0 ? nan_value<Real>() : INFINITY)
                                          : ldexp(1024.0 + mantissa, exponent - 25);
        return (h & 0x8000) ? -v : v;
      };
      for (uint16_t l : lanes) {
        const auto bits = uint32_t(int64_t(a.at(0, l)));
        d[l] = from_half(bits & 0xffff);
        d[L + l] = from_half(bits >> 16);
      }
      break;
    }
    case GLSLstd450PackUnorm4x8: case GLSLstd450PackSnorm4x8: {
      const Src a = arg(0);
      const bool snorm = op == GLSLstd450PackSnorm4x8;
      for (uint16_t l : lanes) {
        uint32_t packed = 0;
        for (uint32_t s = 0; s < 4; ++s) {
          // fmax/fmin, not clamp: NaN packs as 0 instead of reaching an undefined int conversion.
          const Real v = snorm ? round(fmin(fmax(a.at(s, l), Real(-1.0)), Real(1.0)) * 127.0)
                                  : round(fmin(fmax(a.at(s, l), Real(0.0)), Real(1.0)) * 255.0);
          packed |= (uint32_t(int32_t(v)) & 0xff) << (8 * s);
        }
        d[l] = packed;
      }
      break;
    }
    case GLSLstd450UnpackUnorm4x8: case GLSLstd450UnpackSnorm4x8: {
      const Src a = arg(0);
      const bool snorm = op == GLSLstd450UnpackSnorm4x8;
      for (uint16_t l : lanes) {
        const auto bits = uint32_t(int64_t(a.at(0, l)));
        for (uint32_t s = 0; s < 4; ++s) {
          const uint32_t byte = (bits >> (8 * s)) & 0xff;
          d[s * L + l] = R(snorm ? std::clamp<Real>(Real(int8_t(byte)) / 127.0, Real(-1.0), Real(1.0)) : byte / 255.0);
        }
      }
      break;
    }
    case GLSLstd450PackUnorm2x16: case GLSLstd450PackSnorm2x16: {
      const Src a = arg(0);
      const bool snorm = op == GLSLstd450PackSnorm2x16;
      for (uint16_t l : lanes) {
        uint32_t packed = 0;
        for (uint32_t s = 0; s < 2; ++s) {
          const Real v = snorm ? round(fmin(fmax(a.at(s, l), Real(-1.0)), Real(1.0)) * 32767.0)
                                  : round(fmin(fmax(a.at(s, l), Real(0.0)), Real(1.0)) * 65535.0);   // as above
          packed |= (uint32_t(int32_t(v)) & 0xffff) << (16 * s);
        }
        d[l] = packed;
      }
      break;
    }
    case GLSLstd450UnpackUnorm2x16: case GLSLstd450UnpackSnorm2x16: {
      const Src a = arg(0);
      const bool snorm = op == GLSLstd450UnpackSnorm2x16;
      for (uint16_t l : lanes) {
        const auto bits = uint32_t(int64_t(a.at(0, l)));
        for (uint32_t s = 0; s < 2; ++s) {
          const uint32_t word = (bits >> (16 * s)) & 0xffff;
          d[s * L + l] = R(snorm ? std::clamp<Real>(Real(int16_t(word)) / 32767.0, Real(-1.0), Real(1.0)) : word / 65535.0);
        }
      }
      break;
    }
    default:
      return std::unexpected(error(in, "the twin does not support GLSL.std.450 instruction " + std::to_string(int(op))));
  }
  return {};
}

template TwinResult<void> BasicExecutor<double>::execute_ext(uint32_t, const Lanes&);
template TwinResult<void> BasicExecutor<WideReal>::execute_ext(uint32_t, const Lanes&);

}  // namespace twin
