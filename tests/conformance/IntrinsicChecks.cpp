// The definitions are the documented ones (Microsoft's HLSL intrinsic pages, the Cg 3.1
// standard library reference, the GLSL 4.50 specification), written out here in double.
#include "IntrinsicChecks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

namespace shaderbed::conformance {
namespace {

using Values = std::vector<double>;

double to_float(double x) { return double(float(x)); }

Arg scalar(double x) { return Arg{1, 1, {to_float(x)}}; }

Arg vec(std::initializer_list<double> xs) {
  Arg a{1, int(xs.size()), {}};
  for (double x : xs) a.v.push_back(to_float(x));
  return a;
}

// Row-major, as HLSL's floatRxC constructor reads its arguments.
Arg mat(int rows, int cols, std::initializer_list<double> xs) {
  Arg a{rows, cols, {}};
  for (double x : xs) a.v.push_back(to_float(x));
  return a;
}

double largest(const std::vector<Arg>& args) {
  double m = 1;
  for (const Arg& a : args)
    for (double x : a.v) m = std::max(m, std::abs(x));
  return m;
}

double dot(const Values& a, const Values& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

Values scaled(const Values& a, double k) {
  Values r = a;
  for (double& x : r) x *= k;
  return r;
}

Values minus(const Values& a, const Values& b) {
  Values r = a;
  for (size_t i = 0; i < r.size(); ++i) r[i] -= b[i];
  return r;
}

// Row r of a matrix argument, and the product of two row-major matrices.
Values row(const Arg& m, int r) { return Values(m.v.begin() + r * m.cols, m.v.begin() + (r + 1) * m.cols); }

Values column(const Arg& m, int c) {
  Values out;
  for (int r = 0; r < m.rows; ++r) out.push_back(m.v[size_t(r * m.cols + c)]);
  return out;
}

double determinant(const Arg& m) {
  const int n = m.rows;
  if (n == 1) return m.v[0];
  double d = 0;
  for (int c = 0; c < n; ++c) {
    Arg minor{n - 1, n - 1, {}};
    for (int r = 1; r < n; ++r)
      for (int k = 0; k < n; ++k)
        if (k != c) minor.v.push_back(m.v[size_t(r * n + k)]);
    d += (c % 2 ? -1.0 : 1.0) * m.v[size_t(c)] * determinant(minor);
  }
  return d;
}

// A scale for functions that do not cancel: the bound is relative to the result alone.
constexpr double kRelativeOnly = 1e-30;
// A scale for approximated functions whose error is absolute near a zero of the result
// (sin near pi, log near 1): GLSL 4.50 gives log/log2 an absolute bound of 2^-21 there.
constexpr double kAbsolute = 1.0;

class Table {
 public:
  std::vector<Check> checks;

  void add(Check c) {
    if (c.scale == 0) c.scale = largest(c.args);
    checks.push_back(std::move(c));
  }

  // A component-wise function of one argument, checked on each sample (scalars and vectors).
  void unary(const std::string& name, const std::string& hlsl, const std::string& glsl,
             const std::function<double(double)>& f, const std::vector<Arg>& samples, double tolerance = 1e-6,
             unsigned languages = kAll, double scale = kRelativeOnly) {
    for (const Arg& a : samples) {
      Values e;
      for (double x : a.v) e.push_back(f(x));
      add({.intrinsic = name, .args = {a}, .hlsl_cg = hlsl, .glsl = glsl, .languages = languages, .expected = e,
           .tolerance = tolerance, .scale = scale});
    }
  }

  void binary(const std::string& name, const std::string& hlsl, const std::string& glsl,
              const std::function<double(double, double)>& f, const std::vector<std::pair<Arg, Arg>>& samples,
              double tolerance = 1e-6, unsigned languages = kAll) {
    for (const auto& [a, b] : samples) {
      Values e;
      for (size_t i = 0; i < a.v.size(); ++i) e.push_back(f(a.v[i], b.v[b.v.size() == 1 ? 0 : i]));
      add({.intrinsic = name, .args = {a, b}, .hlsl_cg = hlsl, .glsl = glsl, .languages = languages, .expected = e,
           .tolerance = tolerance});
    }
  }

  void ternary(const std::string& name, const std::string& hlsl, const std::string& glsl,
               const std::function<double(double, double, double)>& f, const std::vector<std::vector<Arg>>& samples,
               double tolerance = 1e-6, unsigned languages = kAll) {
    for (const auto& args : samples) {
      Values e;
      for (size_t i = 0; i < args[0].v.size(); ++i) {
        const auto at = [&](int k) { return args[size_t(k)].v[args[size_t(k)].v.size() == 1 ? 0 : i]; };
        e.push_back(f(at(0), at(1), at(2)));
      }
      add({.intrinsic = name, .args = args, .hlsl_cg = hlsl, .glsl = glsl, .languages = languages, .expected = e,
           .tolerance = tolerance});
    }
  }
};

std::string glsl_basis(int n, int r) {
  std::string s = n == 1 ? "float(" : "vec" + std::to_string(n) + "(";
  for (int i = 0; i < n; ++i) s += std::string(i ? ", " : "") + (i == r ? "1.0" : "0.0");
  return s + ")";
}

// mul(a, b) in every order and shape HLSL allows. A matrix result is checked one row at a
// time; GLSL's row r of a matrix M is e_r * M (exact: every other term is a zero).
void add_mul(Table& t, const std::string& shape, const Arg& a, const Arg& b) {
  const bool a_mat = a.rows > 1, b_mat = b.rows > 1;
  const bool a_scalar = a.rows == 1 && a.cols == 1, b_scalar = b.rows == 1 && b.cols == 1;
  if (a_mat && b_mat) {
    for (int r = 0; r < a.rows; ++r) {
      Values e;
      for (int c = 0; c < b.cols; ++c) e.push_back(dot(row(a, r), column(b, c)));
      t.add({.intrinsic = "mul(" + shape + ") row " + std::to_string(r), .args = {a, b},
             .hlsl_cg = "mul($0, $1)[" + std::to_string(r) + "]",
             .glsl = "(" + glsl_basis(a.rows, r) + " * ($0 * $1))", .expected = e});
    }
  } else if (a_mat || b_mat) {
    const Arg& m = a_mat ? a : b;
    const Arg& other = a_mat ? b : a;
    if (other.rows == 1 && other.cols == 1) {  // scalar * matrix: every element scaled
      for (int r = 0; r < m.rows; ++r)
        t.add({.intrinsic = "mul(" + shape + ") row " + std::to_string(r), .args = {a, b},
               .hlsl_cg = "mul($0, $1)[" + std::to_string(r) + "]",
               .glsl = "(" + glsl_basis(m.rows, r) + " * ($0 * $1))", .expected = scaled(row(m, r), other.v[0])});
      return;
    }
    Values e;
    if (a_mat)  // mul(M, v): v is a column
      for (int r = 0; r < m.rows; ++r) e.push_back(dot(row(m, r), other.v));
    else  // mul(v, M): v is a row
      for (int c = 0; c < m.cols; ++c) e.push_back(dot(other.v, column(m, c)));
    t.add({.intrinsic = "mul(" + shape + ")", .args = {a, b}, .hlsl_cg = "mul($0, $1)", .glsl = "($0 * $1)",
           .expected = e});
  } else if (a_scalar || b_scalar) {
    const Values e = a_scalar ? scaled(b.v, a.v[0]) : scaled(a.v, b.v[0]);
    t.add({.intrinsic = "mul(" + shape + ")", .args = {a, b}, .hlsl_cg = "mul($0, $1)", .glsl = "($0 * $1)",
           .expected = e});
  } else {  // vector . vector
    t.add({.intrinsic = "mul(" + shape + ")", .args = {a, b}, .hlsl_cg = "mul($0, $1)", .glsl = "dot($0, $1)",
           .expected = {dot(a.v, b.v)}});
  }
}

std::vector<Check> build() {
  Table t;

  // lit(n.l, n.h, m) = (1, max(n.l, 0), n.l < 0 || n.h < 0 ? 0 : (n.h)^m, 1).
  for (const Values& s : {Values{0.5, 0.5, 4.0}, Values{0.8, 0.9, 16.0}, Values{-0.5, 0.5, 4.0},
                          Values{0.5, -0.5, 4.0}, Values{0.0, 0.5, 2.0}, Values{0.3, 0.7, 0.5}, Values{2.0, 1.5, 3.0},
                          Values{1.0, 0.0, 8.0}, Values{0.25, 1.0, 100.0}}) {
    const std::vector<Arg> args = {scalar(s[0]), scalar(s[1]), scalar(s[2])};
    const double nl = args[0].v[0], nh = args[1].v[0], m = args[2].v[0];
    t.add({.intrinsic = "lit", .args = args, .hlsl_cg = "lit($0, $1, $2)", .languages = kHlslCg,
           .expected = {1.0, std::max(nl, 0.0), nl < 0 || nh < 0 ? 0.0 : std::pow(nh, m), 1.0}, .tolerance = 4e-6});
  }

  // dst(a, b) = (1, a.y * b.y, a.z, b.w).
  for (const auto& [a, b] : {std::pair{vec({1, 2, 3, 4}), vec({5, 6, 7, 8})},
                             std::pair{vec({0, -2.5, 0, 9}), vec({-1, 4, -3, -0.5})},
                             std::pair{vec({7, 1e10, -1e-3, 0}), vec({0, 1e10, 2, 1e30})}})
    t.add({.intrinsic = "dst", .args = {a, b}, .hlsl_cg = "dst($0, $1)", .languages = kHlslCg,
           .expected = {1.0, a.v[1] * b.v[1], a.v[2], b.v[3]}});

  // faceforward(n, i, ng) = dot(i, ng) < 0 ? n : -n (Cg, GLSL; HLSL's page writes
  // -n * sign(dot(i, ng)), which agrees except at dot = 0, where the two documents part:
  // that sample runs for Cg and GLSL only).
  for (const auto& [s, languages] :
       {std::pair{std::vector<Arg>{vec({0, 1, 0}), vec({0.3, -1, 0}), vec({0, 1, 0})}, unsigned(kAll)},
        std::pair{std::vector<Arg>{vec({0, 1, 0}), vec({0.3, 1, 0}), vec({0, 1, 0})}, unsigned(kAll)},
        std::pair{std::vector<Arg>{vec({1, 2, -3}), vec({-4, 0.5, 2}), vec({0.5, 2, 1})}, unsigned(kAll)},
        std::pair{std::vector<Arg>{vec({1, 2, -3}), vec({1, 0, 0}), vec({0, 1, 0})}, unsigned(kCg | kGlsl)}}) {
    const double d = dot(s[1].v, s[2].v);
    t.add({.intrinsic = "faceforward", .args = s, .hlsl_cg = "faceforward($0, $1, $2)",
           .glsl = "faceforward($0, $1, $2)", .languages = languages,
           .expected = d < 0 ? s[0].v : scaled(s[0].v, -1)});
  }

  // reflect(i, n) = i - 2 dot(n, i) n (n is not normalised by the function).
  for (const auto& s : {std::vector<Arg>{vec({1, -1, 0}), vec({0, 1, 0})},
                        std::vector<Arg>{vec({0.25, -0.5, 2}), vec({0.6, 0.8, 0})},
                        std::vector<Arg>{vec({1, 2, 3}), vec({0, 2, 0})},
                        std::vector<Arg>{vec({-3, 1e3, 0.5}), vec({0, 0, 1})}})
    t.add({.intrinsic = "reflect", .args = s, .hlsl_cg = "reflect($0, $1)", .glsl = "reflect($0, $1)",
           .expected = minus(s[0].v, scaled(s[1].v, 2 * dot(s[1].v, s[0].v)))});

  // refract(i, n, eta): k = 1 - eta^2 (1 - dot(n, i)^2); k < 0 ? 0 : eta i - (eta dot(n, i) + sqrt(k)) n.
  const double r = std::sqrt(0.5);
  for (const auto& s : {std::vector<Arg>{vec({0, -1, 0}), vec({0, 1, 0}), scalar(0.75)},
                        std::vector<Arg>{vec({r, -r, 0}), vec({0, 1, 0}), scalar(1.0 / 1.5)},
                        std::vector<Arg>{vec({r, -r, 0}), vec({0, 1, 0}), scalar(1.5)},  // total internal reflection
                        std::vector<Arg>{vec({0.6, -0.8, 0}), vec({0, 1, 0}), scalar(1.0)},
                        std::vector<Arg>{vec({0.28, 0.96, 0}), vec({0, -1, 0}), scalar(1.33)}}) {
    const double eta = s[2].v[0], ni = dot(s[1].v, s[0].v);
    const double k = 1 - eta * eta * (1 - ni * ni);
    t.add({.intrinsic = "refract", .args = s, .hlsl_cg = "refract($0, $1, $2)", .glsl = "refract($0, $1, $2)",
           .expected = k < 0 ? Values{0, 0, 0} : minus(scaled(s[0].v, eta), scaled(s[1].v, eta * ni + std::sqrt(k))),
           .tolerance = 2e-6});
  }

  // smoothstep(a, b, x): t = saturate((x - a) / (b - a)); t^2 (3 - 2t). Defined for a < b.
  t.ternary("smoothstep", "smoothstep($0, $1, $2)", "smoothstep($0, $1, $2)",
            [](double a, double b, double x) {
              const double u = std::clamp((x - a) / (b - a), 0.0, 1.0);
              return u * u * (3 - 2 * u);
            },
            {{scalar(0), scalar(1), scalar(-0.5)}, {scalar(0), scalar(1), scalar(0)}, {scalar(0), scalar(1), scalar(0.25)},
             {scalar(0), scalar(1), scalar(0.5)}, {scalar(0), scalar(1), scalar(1)}, {scalar(0), scalar(1), scalar(7)},
             {scalar(-4), scalar(-2), scalar(-3.5)}, {scalar(10), scalar(1e4), scalar(2500)},
             {vec({0, -1, 2}), vec({1, 1, 3}), vec({0.75, 0, 2.9})}},
            2e-6);

  // step(a, x) = x >= a ? 1 : 0.
  t.binary("step", "step($0, $1)", "step($0, $1)", [](double a, double x) { return x >= a ? 1.0 : 0.0; },
           {{scalar(0.5), scalar(0.25)}, {scalar(0.5), scalar(0.5)}, {scalar(0.5), scalar(0.75)},
            {scalar(0), scalar(-0.0)}, {scalar(-1e30), scalar(-1e30)}, {scalar(1e-30), scalar(0)},
            {vec({1, 2, 3, 4}), vec({0, 2, 5, -4})}});

  // lerp(a, b, s) = a + s (b - a); GLSL's mix is the same function.
  t.ternary("lerp", "lerp($0, $1, $2)", "mix($0, $1, $2)", [](double a, double b, double s) { return a + s * (b - a); },
            {{scalar(2), scalar(6), scalar(0)}, {scalar(2), scalar(6), scalar(1)}, {scalar(2), scalar(6), scalar(0.25)},
             {scalar(2), scalar(6), scalar(2)}, {scalar(2), scalar(6), scalar(-1)}, {scalar(-1e6), scalar(1e6), scalar(0.5)},
             {vec({0, 1, -1}), vec({10, -1, 1}), vec({0.5, 0.5, 0.125})}},
            2e-6);

  // saturate(x) = clamp(x, 0, 1).
  t.unary("saturate", "saturate($0)", "clamp($0, 0.0, 1.0)", [](double x) { return std::clamp(x, 0.0, 1.0); },
          {scalar(-1), scalar(0), scalar(0.5), scalar(1), scalar(2), scalar(-1e30), scalar(1e30), scalar(-0.0),
           vec({-0.5, 0.5, 1.5, 1})});

  // fmod(x, y) = x - y trunc(x / y): the sign of x (HLSL, Cg). GLSL's mod is x - y floor(x / y).
  const std::vector<std::pair<Arg, Arg>> mod_samples = {
      {scalar(5.5), scalar(2)},    {scalar(-5.5), scalar(2)}, {scalar(5.5), scalar(-2)}, {scalar(-5.5), scalar(-2)},
      {scalar(0), scalar(3)},      {scalar(3), scalar(3)},    {scalar(7.25), scalar(0.5)}, {scalar(-0.75), scalar(4)},
      {scalar(1000.5), scalar(3)}, {vec({-1, 1, -2.5}), vec({0.75, 0.75, 1})}};
  t.binary("fmod", "fmod($0, $1)", "", [](double x, double y) { return x - y * std::trunc(x / y); }, mod_samples, 1e-6,
           kHlslCg);
  t.binary("mod (GLSL)", "", "mod($0, $1)", [](double x, double y) { return x - y * std::floor(x / y); }, mod_samples,
           1e-6, kGlsl);

  // frac(x) = x - floor(x).
  t.unary("frac", "frac($0)", "fract($0)", [](double x) { return x - std::floor(x); },
          {scalar(1.25), scalar(-1.25), scalar(0), scalar(-0.0), scalar(3), scalar(-3), scalar(1234.5), scalar(-1e-3),
           vec({0.5, -0.5, 2.75, -2.75})});

  t.unary("log10", "log10($0)", "", [](double x) { return std::log10(x); },
          {scalar(1), scalar(10), scalar(1000), scalar(1e-3), scalar(2), scalar(1e30), scalar(0.5), vec({100, 3, 7})},
          4e-6, kHlslCg, kAbsolute);
  t.unary("exp2", "exp2($0)", "exp2($0)", [](double x) { return std::exp2(x); },
          {scalar(0), scalar(1), scalar(-1), scalar(10), scalar(-10), scalar(0.5), scalar(100), scalar(-100.25),
           vec({3, -3, 0.25})},
          4e-6);
  t.unary("rsqrt", "rsqrt($0)", "inversesqrt($0)", [](double x) { return 1 / std::sqrt(x); },
          {scalar(1), scalar(4), scalar(0.25), scalar(2), scalar(1e30), scalar(1e-30), vec({9, 16, 3})}, 4e-6);
  t.unary("sign", "sign($0)", "sign($0)", [](double x) { return double((x > 0) - (x < 0)); },
          {scalar(-2), scalar(0), scalar(-0.0), scalar(3), scalar(1e-30), scalar(-1e30), vec({-0.5, 0, 0.5})});
  // round: nearest, halves to even (HLSL's page; Cg's newer profiles). GLSL's round leaves
  // halves to the implementation, so GLSL checks roundEven.
  t.unary("round", "round($0)", "roundEven($0)", [](double x) { return std::nearbyint(x); },
          {scalar(1.4), scalar(1.6), scalar(-1.4), scalar(-1.6), scalar(2.5), scalar(3.5), scalar(-2.5), scalar(0.5),
           scalar(-0.5), scalar(1e7 + 0.5), vec({0.49, 4.5, -7.5})});
  t.unary("trunc", "trunc($0)", "trunc($0)", [](double x) { return std::trunc(x); },
          {scalar(1.7), scalar(-1.7), scalar(0.3), scalar(-0.3), scalar(1e10), scalar(-123.999), vec({2.5, -2.5, 0})});

  // atan2(y, x): the angle of (x, y), y first.
  t.binary("atan2", "atan2($0, $1)", "atan($0, $1)", [](double y, double x) { return std::atan2(y, x); },
           {{scalar(1), scalar(1)}, {scalar(1), scalar(-1)}, {scalar(-1), scalar(-1)}, {scalar(-1), scalar(1)},
            {scalar(0), scalar(-1)}, {scalar(2), scalar(0)}, {scalar(-2), scalar(0)}, {scalar(0), scalar(2)},
            {scalar(3), scalar(0.5)}, {scalar(1e-3), scalar(-1e3)}, {vec({1, 0.5}), vec({2, -4})}},
           4e-6);

  // The rest of the common library, each with a few samples of its domain.
  t.unary("abs", "abs($0)", "abs($0)", [](double x) { return std::abs(x); }, {scalar(-2.5), scalar(0), vec({1, -1e30})});
  t.unary("floor", "floor($0)", "floor($0)", [](double x) { return std::floor(x); },
          {scalar(-2.5), scalar(2.5), scalar(-0.0), vec({1.999, -1e-6, 7})});
  t.unary("ceil", "ceil($0)", "ceil($0)", [](double x) { return std::ceil(x); }, {scalar(-2.5), scalar(2.5), vec({1.001, -1e-6, 7})});
  t.unary("sqrt", "sqrt($0)", "sqrt($0)", [](double x) { return std::sqrt(x); },
          {scalar(0), scalar(2), scalar(1e30), scalar(1e-30), vec({4, 0.25})}, 4e-6);
  t.unary("exp", "exp($0)", "exp($0)", [](double x) { return std::exp(x); }, {scalar(0), scalar(1), scalar(-5), scalar(20)}, 8e-6);
  t.unary("log", "log($0)", "log($0)", [](double x) { return std::log(x); }, {scalar(1), scalar(2.718281828), scalar(1e-5), scalar(1e20)}, 8e-6, kAll, kAbsolute);
  t.unary("log2", "log2($0)", "log2($0)", [](double x) { return std::log2(x); }, {scalar(1), scalar(1024), scalar(0.125), scalar(3)}, 4e-6, kAll, kAbsolute);
  t.unary("sin", "sin($0)", "sin($0)", [](double x) { return std::sin(x); }, {scalar(0), scalar(0.5), scalar(-2), scalar(3.1)}, 4e-6, kAll, kAbsolute);
  t.unary("cos", "cos($0)", "cos($0)", [](double x) { return std::cos(x); }, {scalar(0), scalar(0.5), scalar(-2), scalar(3.1)}, 4e-6, kAll, kAbsolute);
  t.unary("tan", "tan($0)", "tan($0)", [](double x) { return std::tan(x); }, {scalar(0), scalar(0.5), scalar(-1.2)}, 8e-6, kAll, kAbsolute);
  // asin, acos: Mesa evaluates them by a polynomial off by up to ~2.1e-4 (asin(0.5) gave
  // 0.5233885, not 0.5235988, on every path); GLSL 4.50 sets them no bound. A front-end
  // fault (a wrong function, argument or branch) is far larger than this bound.
  // asin, acos: Mesa evaluates them by a polynomial off by up to ~2.1e-4 (asin(0.5) gave
  // 0.5233885, not 0.5235988, on every path); GLSL 4.50 sets them no bound. A front-end
  // fault (a wrong function, argument or branch) is far larger than this bound.
  t.unary("asin", "asin($0)", "asin($0)", [](double x) { return std::asin(x); }, {scalar(0), scalar(0.5), scalar(-1), scalar(1)}, 5e-4, kAll, kAbsolute);
  t.unary("acos", "acos($0)", "acos($0)", [](double x) { return std::acos(x); }, {scalar(0), scalar(0.5), scalar(-1), scalar(1)}, 5e-4, kAll, kAbsolute);
  t.unary("atan", "atan($0)", "atan($0)", [](double x) { return std::atan(x); }, {scalar(0), scalar(1), scalar(-30), scalar(1e10)}, 4e-6, kAll, kAbsolute);
  t.unary("sinh", "sinh($0)", "sinh($0)", [](double x) { return std::sinh(x); }, {scalar(0), scalar(0.5), scalar(-3)}, 8e-6, kAll, kAbsolute);
  t.unary("cosh", "cosh($0)", "cosh($0)", [](double x) { return std::cosh(x); }, {scalar(0), scalar(0.5), scalar(-3)}, 8e-6);
  t.unary("tanh", "tanh($0)", "tanh($0)", [](double x) { return std::tanh(x); }, {scalar(0), scalar(0.5), scalar(-3), scalar(20)}, 8e-6, kAll, kAbsolute);
  t.unary("degrees", "degrees($0)", "degrees($0)", [](double x) { return x * 180 / std::numbers::pi; }, {scalar(std::numbers::pi), scalar(-1)});
  t.unary("radians", "radians($0)", "radians($0)", [](double x) { return x * std::numbers::pi / 180; }, {scalar(180), scalar(-1)});
  t.binary("min", "min($0, $1)", "min($0, $1)", [](double a, double b) { return std::min(a, b); },
           {{scalar(1), scalar(-1)}, {vec({1, 2}), vec({3, -4})}});
  t.binary("max", "max($0, $1)", "max($0, $1)", [](double a, double b) { return std::max(a, b); },
           {{scalar(1), scalar(-1)}, {vec({1, 2}), vec({3, -4})}});
  t.binary("pow", "pow($0, $1)", "pow($0, $1)", [](double a, double b) { return std::pow(a, b); },
           {{scalar(2), scalar(10)}, {scalar(0.5), scalar(0.5)}, {scalar(0), scalar(3)}, {scalar(9), scalar(-0.5)},
            {scalar(0.9), scalar(100)}},
           8e-6);
  t.binary("ldexp", "ldexp($0, $1)", "", [](double a, double b) { return std::ldexp(a, int(b)); },
           {{scalar(1.5), scalar(3)}, {scalar(-3), scalar(-2)}}, 1e-6, kHlslCg);
  t.ternary("clamp", "clamp($0, $1, $2)", "clamp($0, $1, $2)",
            [](double x, double lo, double hi) { return std::min(std::max(x, lo), hi); },
            {{scalar(-2), scalar(-1), scalar(1)}, {scalar(0.5), scalar(-1), scalar(1)}, {scalar(5), scalar(-1), scalar(1)}});
  for (const auto& [a, b] : {std::pair{vec({1, 2, 3}), vec({4, 5, 6})}, std::pair{vec({0, 0, 1}), vec({1, 0, 0})}}) {
    t.add({.intrinsic = "cross", .args = {a, b}, .hlsl_cg = "cross($0, $1)", .glsl = "cross($0, $1)",
           .expected = {a.v[1] * b.v[2] - a.v[2] * b.v[1], a.v[2] * b.v[0] - a.v[0] * b.v[2],
                        a.v[0] * b.v[1] - a.v[1] * b.v[0]}});
    t.add({.intrinsic = "dot", .args = {a, b}, .hlsl_cg = "dot($0, $1)", .glsl = "dot($0, $1)", .expected = {dot(a.v, b.v)}});
    t.add({.intrinsic = "distance", .args = {a, b}, .hlsl_cg = "distance($0, $1)", .glsl = "distance($0, $1)",
           .expected = {std::sqrt(dot(minus(a.v, b.v), minus(a.v, b.v)))}, .tolerance = 4e-6});
  }
  for (const Arg& a : {vec({3, 4, 0}), vec({1e-3, -2e-3, 2e-3}), vec({1e15, 1e15, 1e15, 1e15})}) {
    const double len = std::sqrt(dot(a.v, a.v));
    t.add({.intrinsic = "length", .args = {a}, .hlsl_cg = "length($0)", .glsl = "length($0)", .expected = {len},
           .tolerance = 4e-6});
    t.add({.intrinsic = "normalize", .args = {a}, .hlsl_cg = "normalize($0)", .glsl = "normalize($0)",
           .expected = scaled(a.v, 1 / len), .tolerance = 4e-6, .scale = 1});
  }

  // mul in every order and shape; determinant; transpose.
  const Arg m2 = mat(2, 2, {1, 2, 3, 4});
  const Arg m3 = mat(3, 3, {2, -1, 0.5, 0, 3, 1, -2, 0.25, 4});
  const Arg m4 = mat(4, 4, {1, 0, 2, -1, 3, 1, 0, 2, -2, 0.5, 1, 0, 0, 4, -1, 3});
  const Arg m23 = mat(2, 3, {1, 2, 3, 4, 5, 6});
  const Arg m32 = mat(3, 2, {-1, 0.5, 2, -3, 0.25, 4});
  const Arg m34 = mat(3, 4, {1, 0, 0, 5, 0, 1, 0, -6, 0, 0, 1, 7});  // the D3D "float4x3" world matrix's transpose
  const Arg m43 = mat(4, 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 5, -6, 7});
  add_mul(t, "float, float", scalar(3), scalar(-0.5));
  add_mul(t, "float, float3", scalar(2), vec({1, -2, 3}));
  add_mul(t, "float3, float", vec({1, -2, 3}), scalar(2));
  add_mul(t, "float3, float3", vec({1, -2, 3}), vec({4, 0.5, -1}));
  add_mul(t, "float, float2x2", scalar(-2), m2);
  add_mul(t, "float3x3, float", m3, scalar(0.5));
  add_mul(t, "float2, float2x2", vec({5, -1}), m2);
  add_mul(t, "float2x2, float2", m2, vec({5, -1}));
  add_mul(t, "float3, float3x3", vec({1, 2, 3}), m3);
  add_mul(t, "float3x3, float3", m3, vec({1, 2, 3}));
  add_mul(t, "float4, float4x4", vec({1, -1, 2, 1}), m4);
  add_mul(t, "float4x4, float4", m4, vec({1, -1, 2, 1}));
  add_mul(t, "float4, float4x3", vec({2, 3, 4, 1}), m43);
  add_mul(t, "float3x4, float4", m34, vec({2, 3, 4, 1}));
  add_mul(t, "float2, float2x3", vec({1, -1}), m23);
  add_mul(t, "float2x3, float3", m23, vec({1, 0.5, -1}));
  add_mul(t, "float3, float3x2", vec({1, 0.5, -1}), m32);
  add_mul(t, "float3x2, float2", m32, vec({1, -1}));
  add_mul(t, "float2x2, float2x2", m2, mat(2, 2, {0, 1, -1, 2}));
  add_mul(t, "float3x3, float3x3", m3, mat(3, 3, {1, 2, 0, 0, 1, 3, 4, 0, 1}));
  add_mul(t, "float4x4, float4x4", m4, mat(4, 4, {0, 1, 0, 0, 2, 0, 0, 1, 0, 0, 3, 0, 1, 0, 0, -1}));
  add_mul(t, "float2x3, float3x2", m23, m32);
  add_mul(t, "float3x2, float2x3", m32, m23);
  add_mul(t, "float3x4, float4x3", m34, m43);

  for (const Arg& m : {m2, m3, m4, mat(3, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9})})
    t.add({.intrinsic = "determinant(float" + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ")", .args = {m},
           .hlsl_cg = "determinant($0)", .glsl = "determinant($0)", .expected = {determinant(m)}, .tolerance = 2e-6});

  for (const Arg& m : {m2, m23, m43, m4})
    for (int r = 0; r < m.cols; ++r)  // row r of the transpose is column r
      t.add({.intrinsic = "transpose(float" + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ") row " +
                          std::to_string(r),
             .args = {m}, .hlsl_cg = "transpose($0)[" + std::to_string(r) + "]",
             .glsl = "(" + glsl_basis(m.cols, r) + " * transpose($0))", .expected = column(m, r)});

  // Derivatives of functions of the fragment position (pos: the window position, pixel
  // centres at .5, +1 per pixel right and per row down in the image, as D3D's VPOS).
  const auto derivative = [&](const std::string& name, const std::string& hlsl, const std::string& glsl, double e) {
    t.add({.intrinsic = name, .hlsl_cg = hlsl, .glsl = glsl, .expected = {e}, .uniform_flow = true,
           .literal_only = true});
  };
  derivative("ddx(3 pos.x)", "ddx(3.0 * pos.x)", "dFdx(3.0 * pos.x)", 3);
  derivative("ddx(pos.y)", "ddx(pos.y)", "dFdx(pos.y)", 0);
  derivative("ddy(-2.5 pos.y)", "ddy(-2.5 * pos.y)", "dFdy(-2.5 * pos.y)", -2.5);
  derivative("ddy(pos.x)", "ddy(pos.x)", "dFdy(pos.x)", 0);
  derivative("fwidth(2 pos.x - 3 pos.y)", "fwidth(2.0 * pos.x - 3.0 * pos.y)", "fwidth(2.0 * pos.x - 3.0 * pos.y)", 5);

  // Lookups in Tex (kTextureSize square, its mip chain; texel (x, y) of level L holds
  // (x, y, L, 1); nearest filtering and nearest mip: see conformance_texture()). Every
  // lookup runs in uniform control flow, as implicit-LOD ones must.
  const auto lookup = [&](const std::string& name, const std::string& hlsl, const std::string& glsl, Values e,
                          unsigned languages) {
    t.add({.intrinsic = name, .hlsl_cg = hlsl, .glsl = glsl, .languages = languages, .expected = std::move(e),
           .uniform_flow = true, .literal_only = true});
  };
  const auto centre = [](int texel, int level_size) { return fmt::format("{:.9g}", (texel + 0.5) / level_size); };
  const int n = kTextureSize;
  lookup("tex2D at texel (2, 1)", "tex2D(Tex, float2(" + centre(2, n) + ", " + centre(1, n) + "))",
         "texture(Tex, vec2(" + centre(2, n) + ", " + centre(1, n) + "))", {2, 1, 0, 1}, kAll);
  for (const auto& [lod, level] : {std::pair{0.0, 0}, {1.0, 1}, {2.0, 2}, {7.0, 2}, {-1.0, 0}}) {
    const int size = n >> level;
    const std::string u = centre(size - 1, size), v = centre(0, size), l = fmt::format("{:.9g}", lod);
    lookup("tex2Dlod, lod " + l, "tex2Dlod(Tex, float4(" + u + ", " + v + ", 0.0, " + l + "))",
           "textureLod(Tex, vec2(" + u + ", " + v + "), " + l + ")", {double(size - 1), 0, double(level), 1}, kAll);
  }
  // tex2Dproj divides by .w (HLSL); Cg's own tex2Dproj divides by the last of a float3 and
  // is refused by the Cg layer (cg_dialect_test).
  for (double w : {2.0, 0.5, -4.0}) {
    const std::string q = fmt::format("{:.9g}", w);
    const std::string uw = fmt::format("{:.9g}", (1 + 0.5) / n * w), vw = fmt::format("{:.9g}", (3 + 0.5) / n * w);
    lookup("tex2Dproj, w " + q, "tex2Dproj(Tex, float4(" + uw + ", " + vw + ", 0.0, " + q + "))",
           "textureProj(Tex, vec4(" + uw + ", " + vw + ", 0.0, " + q + "))", {1, 3, 0, 1}, kHlsl | kGlsl);
  }
  // Bias and gradients move the level: the coordinates cover one texel of level 0 per
  // pixel (LOD 0) wherever the pixel is, so only the level (.z) is pinned down.
  const std::string per_pixel = fmt::format("pos.xy * {:.9g}", 1.0 / n);
  for (const auto& [bias, level] : {std::pair{0.0, 0}, {1.0, 1}, {2.0, 2}, {-1.0, 0}}) {
    const std::string b = fmt::format("{:.9g}", bias);
    lookup("tex2Dbias, bias " + b, "tex2Dbias(Tex, float4(" + per_pixel + ", 0.0, " + b + ")).z",
           "texture(Tex, " + per_pixel + ", " + b + ").z", {double(level)}, kAll);
  }
  for (const auto& [texels, level] : {std::pair{1.0, 0}, {2.0, 1}, {4.0, 2}}) {
    const std::string g = fmt::format("{:.9g}", texels / n);
    lookup("tex2Dgrad, " + fmt::format("{:g}", texels) + " texels per pixel",
           "tex2Dgrad(Tex, float2(0.5, 0.5), float2(" + g + ", 0.0), float2(0.0, " + g + ")).z",
           "textureGrad(Tex, vec2(0.5, 0.5), vec2(" + g + ", 0.0), vec2(0.0, " + g + ")).z", {double(level)}, kAll);
  }
  return t.checks;
}

std::string number(double x) {
  if (x == 0 && std::signbit(x)) return "-0";
  return fmt::format("{:.9g}", x);
}

}  // namespace

Texture conformance_texture() {
  Texture t{.name = "Tex", .dimensions = 2, .width = kTextureSize, .height = kTextureSize,
            .format = TexelFormat::rgba32_float};
  for (int level = 0, size = kTextureSize; size >= 1; ++level, size /= 2) {
    std::vector<float> texels;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) texels.insert(texels.end(), {float(x), float(y), float(level), 1.0f});
    if (level == 0)
      t.texels = std::move(texels);
    else
      t.mip_levels.push_back(std::move(texels));
  }
  return t;
}

SamplerSettings conformance_sampler() {
  return SamplerSettings{.min_filter = TextureFilter::nearest, .mag_filter = TextureFilter::nearest,
                         .mip_filter = MipFilter::nearest};
}

const std::vector<Check>& intrinsic_checks() {
  static const std::vector<Check> checks = build();
  return checks;
}

std::string describe_args(const std::vector<Arg>& args) {
  std::string out = "(";
  for (size_t i = 0; i < args.size(); ++i) {
    const Arg& a = args[i];
    if (i) out += ", ";
    if (a.v.size() == 1) {
      out += number(a.v[0]);
      continue;
    }
    out += a.rows > 1 ? "float" + std::to_string(a.rows) + "x" + std::to_string(a.cols) + "(" : "float" + std::to_string(a.cols) + "(";
    for (size_t k = 0; k < a.v.size(); ++k) out += (k ? ", " : "") + number(a.v[k]);
    out += ")";
  }
  return out + ")";
}

}  // namespace shaderbed::conformance
