// The real SH basis (sh/Basis.h): closed forms for l <= 3, orthonormality, and the
// Legendre recurrence's accuracy at 12 bands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "sh/Basis.h"
#include "sh/Sampling.h"

namespace sh {
namespace {

using std::numbers::pi;

std::vector<glm::dvec3> random_directions(int count, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  auto uniform = [&] { return double(engine() >> 11) * 0x1.0p-53; };
  std::vector<glm::dvec3> directions;
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * uniform(), phi = 2.0 * pi * uniform();
    const double s = std::sqrt(1.0 - z * z);
    directions.push_back({s * std::cos(phi), s * std::sin(phi), z});
  }
  return directions;
}

// y_l^m for l <= 3 as Cartesian polynomials, worked out by hand from Eq. 5 to 7: the
// constants are sqrt(2) K_l^|m| times P_l^|m|'s leading factor, and odd m carry the
// Condon-Shortley minus sign.
double closed_form(int l, int m, const glm::dvec3& d) {
  const double x = d.x, y = d.y, z = d.z;
  switch (index(l, m)) {
    case 0: return 0.5 / std::sqrt(pi);
    case 1: return -std::sqrt(3 / (4 * pi)) * y;
    case 2: return std::sqrt(3 / (4 * pi)) * z;
    case 3: return -std::sqrt(3 / (4 * pi)) * x;
    case 4: return 0.5 * std::sqrt(15 / pi) * x * y;
    case 5: return -0.5 * std::sqrt(15 / pi) * y * z;
    case 6: return 0.25 * std::sqrt(5 / pi) * (3 * z * z - 1);
    case 7: return -0.5 * std::sqrt(15 / pi) * x * z;
    case 8: return 0.25 * std::sqrt(15 / pi) * (x * x - y * y);
    case 9: return -0.25 * std::sqrt(35 / (2 * pi)) * (3 * x * x * y - y * y * y);
    case 10: return 0.5 * std::sqrt(105 / pi) * x * y * z;
    case 11: return -0.25 * std::sqrt(21 / (2 * pi)) * y * (5 * z * z - 1);
    case 12: return 0.25 * std::sqrt(7 / pi) * (5 * z * z * z - 3 * z);
    case 13: return -0.25 * std::sqrt(21 / (2 * pi)) * x * (5 * z * z - 1);
    case 14: return 0.25 * std::sqrt(105 / pi) * z * (x * x - y * y);
    case 15: return -0.25 * std::sqrt(35 / (2 * pi)) * (x * x * x - 3 * x * y * y);
  }
  return NAN;
}

TEST(Basis, ClosedFormsUpToBand3) {
  for (const glm::dvec3& d : random_directions(50, 1)) {
    std::vector<double> all(16);
    basis_all(4, d, all);
    const double theta = std::acos(d.z), phi = std::atan2(d.y, d.x);
    for (int l = 0; l <= 3; ++l) {
      for (int m = -l; m <= l; ++m) {
        EXPECT_NEAR(basis(l, m, theta, phi), closed_form(l, m, d), 1e-14) << "l=" << l << " m=" << m;
        EXPECT_NEAR(all[index(l, m)], closed_form(l, m, d), 1e-14) << "l=" << l << " m=" << m;
      }
    }
  }
}

TEST(Basis, BasisAllAgreesWithBasisAt12BandsAndAtThePoles) {
  auto directions = random_directions(50, 2);
  directions.push_back({0, 0, 1});
  directions.push_back({0, 0, -1});
  directions.push_back({1, 0, 0});
  for (const glm::dvec3& d : directions) {
    std::vector<double> all(144);
    basis_all(12, d, all);
    const double theta = std::acos(std::clamp(d.z, -1.0, 1.0)), phi = std::atan2(d.y, d.x);
    for (int l = 0; l < 12; ++l)
      for (int m = -l; m <= l; ++m) {
        EXPECT_TRUE(std::isfinite(all[index(l, m)]));
        EXPECT_NEAR(all[index(l, m)], basis(l, m, theta, phi), 1e-13) << "l=" << l << " m=" << m;
      }
  }
}

TEST(Basis, OrthonormalUpTo10BandsByGaussLegendre) {
  // Products of two 10-band functions have degree 18: 10 nodes in cos theta, 19+ azimuths.
  const SampleSet set(gauss_legendre_samples(10, 19), 10);
  const int n = coefficient_count(10);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = i; j < n; ++j) {
      double sum = 0.0;
      for (std::size_t s = 0; s < set.size(); ++s) sum += set.samples()[s].weight * set.basis(s)[i] * set.basis(s)[j];
      worst = std::max(worst, std::abs(sum - (i == j ? 1.0 : 0.0)));
    }
  }
  EXPECT_LT(worst, 1e-12);
}

// The same recurrence in long double: the double one loses nothing visible at 12 bands.
long double legendre_long(int l, int m, long double x) {
  const long double sine = std::sqrt((1.0L - x) * (1.0L + x));
  long double pmm = 1.0L;
  for (int k = 1; k <= m; ++k) pmm *= -(2.0L * k - 1.0L) * sine;
  if (l == m) return pmm;
  long double previous = pmm, current = x * (2.0L * m + 1.0L) * pmm;
  for (int k = m + 2; k <= l; ++k) {
    const long double next = (x * (2.0L * k - 1.0L) * current - (k + m - 1.0L) * previous) / (k - m);
    previous = current;
    current = next;
  }
  return current;
}

TEST(Basis, LegendreAt12BandsMatchesLongDouble) {
  for (int l = 0; l < 12; ++l) {
    for (int m = 0; m <= l; ++m) {
      // The scale of P_l^m on [-1, 1] is about (2m-1)!!: compare relative to it.
      double scale = 1.0;
      for (int k = 1; k <= m; ++k) scale *= 2.0 * k - 1.0;
      for (double x = -1.0; x <= 1.0; x += 1.0 / 64) {
        const double p = legendre(l, m, x);
        ASSERT_TRUE(std::isfinite(p));
        EXPECT_NEAR(p, double(legendre_long(l, m, x)), 1e-13 * scale * (l + 1)) << l << " " << m << " " << x;
      }
    }
  }
  // Known values: P_2^0(x) = (3x^2-1)/2, P_3^3(x) = -15 (1-x^2)^(3/2).
  EXPECT_NEAR(legendre(2, 0, 0.3), (3 * 0.09 - 1) / 2, 1e-15);
  EXPECT_NEAR(legendre(3, 3, 0.6), -15 * std::pow(0.64, 1.5), 1e-13);
}

TEST(Basis, NormalisationHasNoFactorialOverflow) {
  // K_2^1 = sqrt(5/(4 pi) / 6); K_l^-m = K_l^m; at l = m = 100, (200)! would overflow.
  EXPECT_NEAR(normalisation(2, 1), std::sqrt(5 / (4 * pi) / 6), 1e-16);
  EXPECT_EQ(normalisation(5, -3), normalisation(5, 3));
  const double k = normalisation(100, 100);
  EXPECT_TRUE(std::isfinite(k));
  EXPECT_GT(k, 0.0);
  // Ratio check against the log-gamma form.
  EXPECT_NEAR(std::log(k), 0.5 * (std::log(201 / (4 * pi)) - std::lgamma(201.0)), 1e-10);
}

TEST(Basis, SceneToShFrameIsARotationTakingUpToZ) {
  EXPECT_EQ(to_sh_frame({0, 1, 0}), glm::dvec3(0, 0, 1));
  EXPECT_EQ(to_sh_frame({1, 0, 0}), glm::dvec3(1, 0, 0));
  EXPECT_EQ(to_sh_frame({0, 0, 1}), glm::dvec3(0, -1, 0));
  const glm::dvec3 v{0.3, -0.5, 0.7};
  EXPECT_EQ(from_sh_frame(to_sh_frame(v)), v);
  // det = +1: x cross y = z survives the map.
  EXPECT_EQ(glm::cross(to_sh_frame({1, 0, 0}), to_sh_frame({0, 1, 0})), to_sh_frame({0, 0, 1}));
}

TEST(Basis, BandCount) {
  EXPECT_EQ(band_count(0), 0);
  EXPECT_EQ(band_count(1), 1);
  EXPECT_EQ(band_count(8), 2);
  EXPECT_EQ(band_count(9), 3);
  EXPECT_EQ(band_count(25), 5);
  EXPECT_EQ(index(2, -1), 5);
}

}  // namespace
}  // namespace sh
