// SH rotation by the Ivanic-Ruedenberg recursion (Rotation.h).
//
// The recursion is stated for real harmonics without the Condon-Shortley phase, whose
// band 1 is (y, z, x) with positive signs. The book's y_l^m carry (-1)^m (Basis.h), so
// y = S y~ with S = diag((-1)^m), and the blocks become D = S D~ S: entry (m, m') changes
// sign when m + m' is odd. The recursion runs on D~ and the signs are applied at the end.
#include "sh/Rotation.h"

#include <algorithm>
#include <cmath>

#include "sh/Basis.h"

namespace sh {

namespace {

// Row/column of R that band 1's index m reads: y_1^-1 ~ y, y_1^0 ~ z, y_1^1 ~ x.
constexpr int axis_of(int m) { return m == -1 ? 1 : m == 0 ? 2 : 0; }

// One band's matrix indexed by m, m' in [-l, l].
struct BandView {
  const double* data;
  int l;
  double operator()(int m, int mp) const { return data[(m + l) * (2 * l + 1) + (mp + l)]; }
};

}  // namespace

Rotation::Rotation(const glm::dmat3& r, int bands) : bands_(std::max(bands, 0)), blocks_(offset(bands_)) {
  if (bands_ == 0) return;
  blocks_[0] = 1.0;
  if (bands_ == 1) return;
  for (int m = -1; m <= 1; ++m)
    for (int mp = -1; mp <= 1; ++mp) blocks_[offset(1) + (m + 1) * 3 + (mp + 1)] = r[axis_of(mp)][axis_of(m)];

  const BandView r1{&blocks_[offset(1)], 1};
  for (int l = 2; l < bands_; ++l) {
    const BandView prev{&blocks_[offset(l - 1)], l - 1};
    double* out = &blocks_[offset(l)];

    // The paper's P: band 1's row i combined with band l-1's row a, column b (|b| <= l).
    auto p = [&](int i, int a, int b) {
      if (b == l) return r1(i, 1) * prev(a, l - 1) - r1(i, -1) * prev(a, -l + 1);
      if (b == -l) return r1(i, 1) * prev(a, -l + 1) + r1(i, -1) * prev(a, l - 1);
      return r1(i, 0) * prev(a, b);
    };

    for (int m = -l; m <= l; ++m) {
      const int am = std::abs(m);
      const double d = m == 0 ? 1.0 : 0.0;
      for (int mp = -l; mp <= l; ++mp) {
        const double denominator = std::abs(mp) < l ? double(l + mp) * (l - mp) : double(2 * l) * (2 * l - 1);
        const double u = std::sqrt(double(l + m) * (l - m) / denominator);
        const double v = 0.5 * std::sqrt((1.0 + d) * (l + am - 1.0) * (l + am) / denominator) * (1.0 - 2.0 * d);
        const double w = -0.5 * std::sqrt(std::max(0.0, (l - am - 1.0) * (l - am)) / denominator) * (1.0 - d);

        // Terms whose coefficient is zero are skipped: their P would read outside band l-1.
        double sum = 0.0;
        if (u != 0.0) sum += u * p(0, m, mp);
        if (v != 0.0) {
          double big_v;
          if (m == 0)
            big_v = p(1, 1, mp) + p(-1, -1, mp);
          else if (m > 0)
            big_v = m == 1 ? std::sqrt(2.0) * p(1, 0, mp) : p(1, m - 1, mp) - p(-1, -m + 1, mp);
          else
            big_v = m == -1 ? std::sqrt(2.0) * p(-1, 0, mp) : p(1, m + 1, mp) + p(-1, -m - 1, mp);
          sum += v * big_v;
        }
        if (w != 0.0) {
          const double big_w = m > 0 ? p(1, m + 1, mp) + p(-1, -m - 1, mp) : p(1, m - 1, mp) - p(-1, -m + 1, mp);
          sum += w * big_w;
        }
        out[(m + l) * (2 * l + 1) + (mp + l)] = sum;
      }
    }
  }

  for (int l = 1; l < bands_; ++l)
    for (int m = -l; m <= l; ++m)
      for (int mp = -l; mp <= l; ++mp)
        if ((m + mp) % 2 != 0) blocks_[offset(l) + (m + l) * (2 * l + 1) + (mp + l)] *= -1.0;
}

void Rotation::apply(std::span<const double> in, std::span<double> out) const {
  const int bands = std::min({bands_, band_count(in.size()), band_count(out.size())});
  for (int l = 0; l < bands; ++l) {
    const auto d = block(l);
    const int n = 2 * l + 1, first = l * l;
    for (int row = 0; row < n; ++row) {
      double sum = 0.0;
      for (int column = 0; column < n; ++column) sum += d[row * n + column] * in[first + column];
      out[first + row] = sum;
    }
  }
}

void Rotation::apply(std::span<const glm::dvec3> in, std::span<glm::dvec3> out) const {
  const int bands = std::min({bands_, band_count(in.size()), band_count(out.size())});
  for (int l = 0; l < bands; ++l) {
    const auto d = block(l);
    const int n = 2 * l + 1, first = l * l;
    for (int row = 0; row < n; ++row) {
      glm::dvec3 sum(0.0);
      for (int column = 0; column < n; ++column) sum += d[row * n + column] * in[first + column];
      out[first + row] = sum;
    }
  }
}

std::vector<double> rotate(int bands, const glm::dmat3& r, std::span<const double> in) {
  bands = std::clamp(bands, 0, band_count(in.size()));
  std::vector<double> out(std::size_t(coefficient_count(bands)));
  Rotation(r, bands).apply(in, out);
  return out;
}

std::vector<glm::dvec3> rotate(int bands, const glm::dmat3& r, std::span<const glm::dvec3> in) {
  bands = std::clamp(bands, 0, band_count(in.size()));
  std::vector<glm::dvec3> out(std::size_t(coefficient_count(bands)));
  Rotation(r, bands).apply(in, out);
  return out;
}

glm::dmat3 to_sh_frame(const glm::dmat3& scene_rotation) {
  // Columns of C are the images of the scene's axes: x -> x, y -> z, z -> -y.
  const glm::dmat3 c(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  return c * scene_rotation * glm::transpose(c);
}

}  // namespace sh
