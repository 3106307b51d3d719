#pragma once
// Rotation of SH coefficient vectors (8.2.3, rotational invariance; D3DXSHRotate in Ch. 9).
//
// Meaning: for a rotation matrix R (SH frame, acting on column vectors, det R = +1),
// rotating the coefficients of f by R gives the coefficients of g(w) = f(R^T w): the
// function turned by R, so a lobe that pointed along d points along R d afterwards.
// Each band l rotates on its own by a (2l+1) x (2l+1) orthogonal block D^l with
// y_lm(R w) = sum_m' D^l_mm' y_lm'(w), built by the Ivanic-Ruedenberg recursion
// (J. Phys. Chem. 100, 6342 (1996); erratum 102, 9099 (1998)) from band 1, which is R
// itself read in the (y, z, x) order of y_1^-1, y_1^0, y_1^1.
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sh {

class Rotation {
 public:
  // `r` must be a proper rotation (orthonormal, det +1), in the SH frame.
  Rotation(const glm::dmat3& r, int bands);

  int bands() const { return bands_; }
  // D^l_mm' for |m|, |m'| <= l < bands().
  double element(int l, int m, int m_prime) const {
    return blocks_[offset(l) + std::size_t((m + l) * (2 * l + 1) + (m_prime + l))];
  }
  // Band l's block, row major (row m + l, column m' + l).
  std::span<const double> block(int l) const {
    return std::span<const double>(blocks_).subspan(offset(l), std::size_t((2 * l + 1) * (2 * l + 1)));
  }

  // out = D in, band by band, for the complete bands both spans hold (at most bands());
  // the rest of `out` is left alone. The spans must not overlap.
  void apply(std::span<const double> in, std::span<double> out) const;
  void apply(std::span<const glm::dvec3> in, std::span<glm::dvec3> out) const;

 private:
  static std::size_t offset(int l) {
    // sum of (2k+1)^2 for k < l
    return std::size_t(l) * (4 * std::size_t(l) * l - 1) / 3;
  }

  int bands_;
  std::vector<double> blocks_;
};

// The coefficients of f(R^T w) from those of f: min(bands, complete bands of in)^2 of them.
std::vector<double> rotate(int bands, const glm::dmat3& r, std::span<const double> in);
std::vector<glm::dvec3> rotate(int bands, const glm::dmat3& r, std::span<const glm::dvec3> in);

// A rotation of the scene's y-up frame expressed in the SH frame: C R C^T, where C is
// to_sh_frame (Basis.h). Rotating scene-space light by R is rotating its SH by this.
glm::dmat3 to_sh_frame(const glm::dmat3& scene_rotation);

}  // namespace sh
