// Real spherical harmonics (Basis.h): the book's Eq. 5 to 8, with the non-recursive
// Legendre recurrence and a factorial-free K, so every band up to the table's size and far
// beyond stays finite in double.
#include "sh/Basis.h"

#include <array>
#include <cmath>
#include <numbers>

namespace sh {

namespace {

// basis_all reads K from a table so the hot loop has no sqrt; bands past it compute K.
constexpr int table_bands = 32;

// sqrt(2) K_l^|m| for m != 0, K_l^0 for m = 0: the whole constant factor of y_l^m.
double basis_factor(int l, int m) { return (m == 0 ? 1.0 : std::numbers::sqrt2) * normalisation(l, m); }

const std::array<double, table_bands * table_bands>& factor_table() {
  static const auto table = [] {
    std::array<double, table_bands * table_bands> t{};
    for (int l = 0; l < table_bands; ++l)
      for (int m = 0; m <= l; ++m) t[index(l, m)] = basis_factor(l, m);
    return t;
  }();
  return table;
}

}  // namespace

double legendre(int l, int m, double x) {
  // P_m^m = (-1)^m (2m-1)!! (1-x^2)^(m/2), built one factor at a time.
  const double sine = std::sqrt((1.0 - x) * (1.0 + x));
  double pmm = 1.0;
  for (int k = 1; k <= m; ++k) pmm *= -(2.0 * k - 1.0) * sine;
  if (l == m) return pmm;
  // P_{m+1}^m = x (2m+1) P_m^m, then (l-m) P_l^m = x (2l-1) P_{l-1}^m - (l+m-1) P_{l-2}^m.
  double previous = pmm;
  double current = x * (2.0 * m + 1.0) * pmm;
  for (int k = m + 2; k <= l; ++k) {
    const double next = (x * (2.0 * k - 1.0) * current - (k + m - 1.0) * previous) / (k - m);
    previous = current;
    current = next;
  }
  return current;
}

double normalisation(int l, int m) {
  // sqrt((l-|m|)!/(l+|m|)!) as the product of 1/sqrt(k) for k = l-|m|+1 .. l+|m|: no
  // factorial overflows, and the ratio itself (1/200! at l = m = 100) does not underflow.
  const int a = std::abs(m);
  double root_ratio = 1.0;
  for (int k = l - a + 1; k <= l + a; ++k) root_ratio /= std::sqrt(double(k));
  return std::sqrt((2.0 * l + 1.0) / (4.0 * std::numbers::pi)) * root_ratio;
}

double basis(int l, int m, double theta, double phi) {
  // Eq. 5 as the book's code implements it: m < 0 takes K, P and sin of |m|.
  const double x = std::cos(theta);
  if (m == 0) return normalisation(l, 0) * legendre(l, 0, x);
  const int a = std::abs(m);
  const double azimuth = m > 0 ? std::cos(a * phi) : std::sin(a * phi);
  return std::numbers::sqrt2 * normalisation(l, a) * azimuth * legendre(l, a, x);
}

void basis_all(int bands, const glm::dvec3& direction, std::span<double> out) {
  // P_l^m(z) = (1-z^2)^(m/2) Q_l^m(z), and (1-z^2)^(m/2) (cos m phi, sin m phi) is
  // (Re, Im) of (x + iy)^m: so no trigonometry and no sqrt, and the poles need no care.
  const double x = direction.x, y = direction.y, z = direction.z;
  const auto& table = factor_table();
  auto factor = [&](int l, int m) { return l < table_bands ? table[index(l, m)] : basis_factor(l, m); };

  double re = 1.0, im = 0.0;  // (x + iy)^m
  double qmm = 1.0;           // Q_m^m = (-1)^m (2m-1)!!
  for (int m = 0; m < bands; ++m) {
    double previous = 0.0, current = qmm;
    for (int l = m; l < bands; ++l) {
      if (l == m + 1) {
        previous = current;
        current = z * (2.0 * m + 1.0) * current;
      } else if (l > m + 1) {
        const double next = (z * (2.0 * l - 1.0) * current - (l + m - 1.0) * previous) / (l - m);
        previous = current;
        current = next;
      }
      const double value = factor(l, m) * current;
      if (m == 0) {
        out[index(l, 0)] = value;
      } else {
        out[index(l, m)] = value * re;
        out[index(l, -m)] = value * im;
      }
    }
    qmm *= -(2.0 * m + 1.0);
    const double next_re = x * re - y * im;
    im = x * im + y * re;
    re = next_re;
  }
}

}  // namespace sh
