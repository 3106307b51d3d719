// Sample sets and projection (sh/Sampling.h, sh/Projection.h), and the book's worked
// example (Figs. 8.13/8.14): exact, jittered, and as printed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "sh/Basis.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Sampling.h"

namespace sh {
namespace {

using std::numbers::pi;

// ---- sample sets --------------------------------------------------------------------------

TEST(Sampling, JitteredGridHasOneUniformSamplePerCell) {
  const int grid = 20;
  const std::vector<Sample> samples = jittered_samples(grid, 5);
  ASSERT_EQ(samples.size(), 400u);
  double total = 0;
  for (int a = 0; a < grid; ++a) {
    for (int b = 0; b < grid; ++b) {
      const Sample& s = samples[a * grid + b];
      total += s.weight;
      EXPECT_NEAR(glm::length(s.direction), 1.0, 1e-15);
      // cos theta = 1 - 2x and phi = 2 pi y: recover the cell.
      const double x = (1 - s.direction.z) / 2;
      double phi = std::atan2(s.direction.y, s.direction.x);
      if (phi < 0) phi += 2 * pi;
      EXPECT_GE(x * grid, a - 1e-9);
      EXPECT_LE(x * grid, a + 1 + 1e-9);
      EXPECT_GE(phi / (2 * pi) * grid, b - 1e-9);
      EXPECT_LE(phi / (2 * pi) * grid, b + 1 + 1e-9);
    }
  }
  EXPECT_NEAR(total, 4 * pi, 1e-12);
}

TEST(Sampling, JitteredGridIsReproducible) {
  const auto a = jittered_samples(8, 42), b = jittered_samples(8, 42), c = jittered_samples(8, 43);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].direction, b[i].direction);
  EXPECT_NE(a[0].direction, c[0].direction);
  // mt19937_64 is specified to the bit and the conversion is ours: the default set is pinned
  // (to libm's last bits).
  const glm::dvec3 first = jittered_samples(100)[0].direction;
  EXPECT_NEAR(first.x, 0.13581161935692768, 1e-14);
  EXPECT_NEAR(first.y, 0.0036595772521268613, 1e-14);
  EXPECT_NEAR(first.z, 0.99072792003757759, 1e-14);
}

TEST(Sampling, GaussLegendreNodesAndWeights) {
  const GaussLegendre two = gauss_legendre(2), three = gauss_legendre(3);
  EXPECT_NEAR(two.nodes[0], -1 / std::sqrt(3.0), 4e-16);
  EXPECT_NEAR(two.weights[1], 1.0, 1e-15);
  EXPECT_NEAR(three.nodes[1], 0.0, 4e-16);
  EXPECT_NEAR(three.nodes[2], std::sqrt(0.6), 4e-16);
  EXPECT_NEAR(three.weights[0], 5.0 / 9, 1e-15);
  EXPECT_NEAR(three.weights[1], 8.0 / 9, 1e-15);
  for (int n : {1, 5, 17, 64, 200}) {
    const GaussLegendre rule = gauss_legendre(n);
    // Exact for x^(2n-2): integral over [-1, 1] is 2 / (2n-1).
    double sum = 0, moment = 0;
    for (int k = 0; k < n; ++k) {
      sum += rule.weights[k];
      moment += rule.weights[k] * std::pow(rule.nodes[k], 2 * n - 2);
      if (k > 0) {
        EXPECT_LT(rule.nodes[k - 1], rule.nodes[k]);
      }
    }
    EXPECT_NEAR(sum, 2.0, 1e-13) << n;
    EXPECT_NEAR(moment, 2.0 / (2 * n - 1), 1e-13) << n;
  }
}

TEST(Sampling, GaussLegendreSetWeighsTheSphere) {
  double total = 0;
  for (const Sample& s : gauss_legendre_samples(7, 13)) total += s.weight;
  EXPECT_NEAR(total, 4 * pi, 1e-13);
}

// ---- projection ----------------------------------------------------------------------------

TEST(Projection, BandLimitedFunctionsComeBackExactly) {
  std::vector<double> c(36);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = std::sin(1.0 + 3.0 * i);
  const SampleSet set(gauss_legendre_samples(6, 11), 6);
  const std::vector<double> back = project([&](const glm::dvec3& w) { return evaluate(c, w); }, set);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(back[i], c[i], 1e-13);
  // Onto fewer bands: the leading coefficients.
  EXPECT_EQ(project([&](const glm::dvec3& w) { return evaluate(c, w); }, set, 3).size(), 9u);
  // RGB: per channel.
  const auto rgb = project_rgb([&](const glm::dvec3& w) { return glm::dvec3(1, 2, 3) * evaluate(c, w); }, set);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(rgb[i].b, 3 * c[i], 1e-12);
  EXPECT_NEAR(evaluate(rgb, {0, 0, 1}).g, 2 * evaluate(c, {0, 0, 1}), 1e-12);
}

TEST(Projection, DotIsTheProductIntegralAndAddPads) {
  std::vector<double> a(16), b(9);
  for (int i = 0; i < 16; ++i) a[i] = std::cos(0.5 + i);
  for (int i = 0; i < 9; ++i) b[i] = std::sin(0.2 + 2 * i);
  const SampleSet set(gauss_legendre_samples(8, 16), 4);
  double integral = 0;
  for (const Sample& s : set.samples()) integral += s.weight * evaluate(a, s.direction) * evaluate(b, s.direction);
  EXPECT_NEAR(dot(a, b), integral, 1e-13);
  const std::vector<double> sum = add(a, b);
  ASSERT_EQ(sum.size(), 16u);
  EXPECT_EQ(sum[3], a[3] + b[3]);
  EXPECT_EQ(sum[12], a[12]);
  EXPECT_EQ(scale(b, 2.0)[4], 2 * b[4]);
  const std::vector<glm::dvec3> light(9, glm::dvec3(1, 2, 3));
  EXPECT_NEAR(dot(light, std::span<const double>(b)).z, 3 * dot(std::vector<double>(9, 1.0), b), 1e-14);
}

TEST(Projection, ZonalProjectionMatchesQuadrature) {
  // g(t) = t^3 - t on the cap t >= 0.3 about an axis: smooth in the interior of the cap, so
  // compare with a zonal polynomial over the whole sphere, which is band-limited (l <= 3).
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, -0.5));
  const auto g = [](double t) { return t * t * t - t; };
  const std::vector<double> exact = project_zonal(6, axis, g, -1.0, 3);
  const SampleSet set(gauss_legendre_samples(6, 11), 6);
  const std::vector<double> numeric = project([&](const glm::dvec3& w) { return g(glm::dot(w, axis)); }, set);
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(exact[i], numeric[i], 1e-13) << i;
  EXPECT_NEAR(exact[index(5, 2)], 0.0, 1e-14);  // degree 3: nothing above band 3
}

// ---- the book's worked example (Ch. 8, Figs. 8.13 and 8.14) ---------------------------------

// The digest's deterministic integration of Eq. 14 (6 d.p.), and the book's printed Monte
// Carlo values (100 x 100 jittered samples), i = 0 .. 24.
const double digest_exact[25] = {
    0.398807,  -0.210524, 0.286539,  0.281817, -0.314993,  //
    0,         0.131386,  0,         0.093179, -0.249606,  //
    0,         0.123359,  0.303884,  -0.165134, 0,         //
    -0.092241, -0.100233, 0,         0.133554,  0,         //
    0.343242,  0,         -0.039507, 0,         -0.154594};
const double book_printed[25] = {
    0.399249,  -0.210748, 0.286867,  0.282772,  -0.315302,  //
    -0.000398, 0.131591,  0.000977,  0.093585,  -0.249934,  //
    -0.000721, 0.122896,  0.304576,  -0.164276, -0.000615,  //
    -0.091265, -0.101271, -0.000139, 0.132715,  -0.000166,  //
    0.344469,  0.001542,  -0.041332, -0.000069, -0.153648};

// The digest's midpoint rule: 600 x 1200 cells in (theta, phi), weight sin(theta) dtheta dphi.
std::vector<double> digest_midpoint_rule() {
  const int n_theta = 600, n_phi = 1200;
  const double dtheta = pi / n_theta, dphi = 2 * pi / n_phi;
  std::vector<double> c(25, 0.0), y(25);
  for (int a = 0; a < n_theta; ++a) {
    const double theta = (a + 0.5) * dtheta;
    for (int b = 0; b < n_phi; ++b) {
      const double phi = (b + 0.5) * dphi;
      const glm::dvec3 d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      const double f = book_test_function(theta, phi) * std::sin(theta) * dtheta * dphi;
      if (f == 0) continue;
      basis_all(5, d, y);
      for (int i = 0; i < 25; ++i) c[i] += f * y[i];
    }
  }
  return c;
}

TEST(BookExample, ExactCoefficientsMatchTheDigest) {
  const std::vector<double> exact = book_test_coefficients_exact(5);
  ASSERT_EQ(exact.size(), 25u);
  // By hand: c_0 = 2 pi y_0 (integral of 5t-4 over [0.8, 1] + of 4t-3 over [0.75, 1])
  // = 2 pi (0.1 + 0.125) / (2 sqrt(pi)) = 0.225 sqrt(pi).
  EXPECT_NEAR(exact[0], 0.225 * std::sqrt(pi), 1e-15);
  for (int i : {5, 7, 10, 14, 17, 19, 21, 23}) EXPECT_NEAR(exact[i], 0.0, 1e-15) << "i = " << i;
  // The digest's values are a 600 x 1200 midpoint rule, not exact: the first lobe's kink at
  // cos theta = 0.8 lies along a grid row, so its zonal coefficients (i = 0, 2, 6, 12, 20)
  // carry the rule's O(h^2) error, up to 8e-6. Elsewhere they agree to their 6 d.p.
  const std::vector<double> midpoint = digest_midpoint_rule();
  for (int i = 0; i < 25; ++i) {
    const bool zonal = i == 0 || i == 2 || i == 6 || i == 12 || i == 20;
    EXPECT_NEAR(exact[i], digest_exact[i], zonal ? 1e-5 : 1e-6) << "i = " << i;
    // The same rule here reproduces the digest's numbers, so the difference is the rule's.
    EXPECT_NEAR(midpoint[i], digest_exact[i], 1e-6) << "i = " << i;
  }
}

TEST(BookExample, JitteredProjectionAsTheBook) {
  const std::vector<double> exact = book_test_coefficients_exact(5);
  const std::vector<double> jittered = book_test_coefficients(5, 100);
  double worst = 0, worst_book = 0;
  std::printf(" i   jittered 100x100    exact        |diff|\n");
  for (int i = 0; i < 25; ++i) {
    const double diff = std::abs(jittered[i] - exact[i]);
    std::printf("%2d  %11.6f  %11.6f  %10.2e\n", i, jittered[i], exact[i], diff);
    worst = std::max(worst, diff);
    worst_book = std::max(worst_book, std::abs(book_printed[i] - exact[i]));
    EXPECT_NEAR(jittered[i], exact[i], 5e-3) << "i = " << i;
    EXPECT_NEAR(book_printed[i], exact[i], 2e-3) << "i = " << i;
  }
  std::printf("max |jittered - exact| = %.3e, max |book - exact| = %.3e\n", worst, worst_book);
}

TEST(BookExample, FunctionByAnglesAndByDirectionAgree) {
  for (double theta = 0.05; theta < pi; theta += 0.3)
    for (double phi = 0.1; phi < 2 * pi; phi += 0.4) {
      const glm::dvec3 d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      EXPECT_NEAR(book_test_function(d), book_test_function(theta, phi), 1e-13);
    }
  EXPECT_NEAR(book_test_function(0.0, 0.0), 1.0, 1e-15);  // 5 cos 0 - 4
}

TEST(BookExample, GaussLegendreProjectionConvergesToTheExactValues) {
  // The kinks (max(0, .)) limit a product rule to second order; 200 x 400 is within 1e-4.
  const SampleSet set(gauss_legendre_samples(200, 400), 5);
  const std::vector<double> numeric = project([](const glm::dvec3& d) { return book_test_function(d); }, set);
  const std::vector<double> exact = book_test_coefficients_exact(5);
  for (int i = 0; i < 25; ++i) EXPECT_NEAR(numeric[i], exact[i], 1e-4) << "i = " << i;
}

}  // namespace
}  // namespace sh
