// SH rotation (sh/Rotation.h): rotating coefficients by R is projecting f(R^T w).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "sh/Basis.h"
#include "sh/Lights.h"
#include "sh/Projection.h"
#include "sh/Rotation.h"
#include "sh/Sampling.h"

namespace sh {
namespace {

using std::numbers::pi;

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  // A uniformly random rotation, from a uniformly random unit quaternion (Shoemake).
  glm::dmat3 rotation() {
    const double u1 = uniform(), u2 = 2 * pi * uniform(), u3 = 2 * pi * uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
    // Columns are the images of the axes.
    return glm::dmat3(glm::dvec3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)),
                      glm::dvec3(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)),
                      glm::dvec3(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)));
  }
  std::vector<double> coefficients(int bands) {
    std::vector<double> c(std::size_t(coefficient_count(bands)));
    for (double& v : c) v = 2 * uniform() - 1;
    return c;
  }

 private:
  std::mt19937_64 engine_;
};

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

TEST(Rotation, MatchesProjectingTheRotatedFunction) {
  Random random(7);
  for (int bands = 1; bands <= 8; ++bands) {
    // f(R^T w) y(w) has degree 2 (bands - 1): exact with bands nodes and 2 bands azimuths.
    const SampleSet set(gauss_legendre_samples(bands, 2 * bands), bands);
    for (int trial = 0; trial < 3; ++trial) {
      const glm::dmat3 r = random.rotation();
      const std::vector<double> f = random.coefficients(bands);
      const auto turned = [&](const glm::dvec3& w) { return evaluate(f, glm::transpose(r) * w); };
      EXPECT_LT(max_difference(rotate(bands, r, f), project(turned, set)), 1e-10) << bands << " bands";
    }
  }
}

TEST(Rotation, ALobeAlongDPointsAlongRdAfterwards) {
  Random random(8);
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.2, -0.4, 0.9));
  for (int trial = 0; trial < 5; ++trial) {
    const glm::dmat3 r = random.rotation();
    EXPECT_LT(max_difference(rotate(6, r, clamped_cosine(6, d)), clamped_cosine(6, r * d)), 1e-13);
  }
}

TEST(Rotation, IdentityAndComposition) {
  Random random(9);
  const std::vector<double> f = random.coefficients(10);
  EXPECT_LT(max_difference(rotate(10, glm::dmat3(1.0), f), f), 1e-15);
  for (int trial = 0; trial < 5; ++trial) {
    const glm::dmat3 r1 = random.rotation(), r2 = random.rotation();
    // g1 = f(R1^T w), g2 = g1(R2^T w) = f((R2 R1)^T w).
    EXPECT_LT(max_difference(rotate(10, r2, rotate(10, r1, f)), rotate(10, r2 * r1, f)), 1e-12);
    EXPECT_LT(max_difference(rotate(10, glm::transpose(r1), rotate(10, r1, f)), f), 1e-12);
  }
}

TEST(Rotation, BlocksAreOrthogonal) {
  Random random(10);
  const Rotation rotation(random.rotation(), 10);
  for (int l = 0; l < 10; ++l) {
    for (int a = -l; a <= l; ++a)
      for (int b = -l; b <= l; ++b) {
        double sum = 0;
        for (int k = -l; k <= l; ++k) sum += rotation.element(l, a, k) * rotation.element(l, b, k);
        EXPECT_NEAR(sum, a == b ? 1.0 : 0.0, 1e-12) << l;
      }
  }
}

TEST(Rotation, RgbRotatesEachChannel) {
  Random random(11);
  const glm::dmat3 r = random.rotation();
  const std::vector<double> red = random.coefficients(4), green = random.coefficients(4), blue = random.coefficients(4);
  std::vector<glm::dvec3> rgb(16);
  for (int i = 0; i < 16; ++i) rgb[i] = {red[i], green[i], blue[i]};
  const std::vector<glm::dvec3> turned = rotate(4, r, rgb);
  const std::vector<double> turned_green = rotate(4, r, green);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(turned[i].g, turned_green[i], 1e-15);
}

TEST(Rotation, SceneRotationsMapToTheShFrame) {
  Random random(12);
  const glm::dmat3 scene = random.rotation();
  const glm::dvec3 v{0.3, 0.5, -0.2};
  const glm::dvec3 a = to_sh_frame(scene * v), b = to_sh_frame(scene) * to_sh_frame(v);
  EXPECT_NEAR(glm::length(a - b), 0.0, 1e-15);
}

TEST(Rotation, ShortInputRotatesItsCompleteBands) {
  Random random(13);
  const std::vector<double> f = random.coefficients(3);
  EXPECT_EQ(rotate(5, random.rotation(), f).size(), 9u);
}

}  // namespace
}  // namespace sh
