#pragma once
// Real spherical harmonics as the book defines them (Ch. 8, Eq. 5 to 8): Condon-Shortley
// phase in P_m^m, K_l^m normalisation, single index i = l(l+1) + m, n bands = n^2
// coefficients. Directions are in the SH frame, z up (the book's OpenGL code); the scene is
// y up and enters through to_sh_frame (docs/sh.md says why it is a rotation, not a swap).
#include <cstddef>
#include <span>

#include <glm/glm.hpp>

namespace sh {

constexpr int index(int l, int m) { return l * (l + 1) + m; }
constexpr int coefficient_count(int bands) { return bands * bands; }
// The number of complete bands in a vector of that many coefficients (floor of the root).
constexpr int band_count(std::size_t coefficients) {
  int bands = 0;
  while (std::size_t(bands + 1) * std::size_t(bands + 1) <= coefficients) ++bands;
  return bands;
}

// The scene's y-up object space to the SH frame: a proper rotation taking +y to +z.
inline glm::dvec3 to_sh_frame(const glm::dvec3& v) { return {v.x, -v.z, v.y}; }
inline glm::dvec3 from_sh_frame(const glm::dvec3& v) { return {v.x, v.z, -v.y}; }

// Associated Legendre polynomial P_l^m(x), 0 <= m <= l, |x| <= 1, with the Condon-Shortley
// phase; by the non-recursive recurrence, no factorials, finite in double far beyond 10 bands.
double legendre(int l, int m, double x);

// K_l^m = sqrt((2l+1)/(4 pi) (l-|m|)!/(l+|m|)!), computed as a product (no overflow).
double normalisation(int l, int m);

// y_l^m at spherical angles (theta from +z, phi from +x toward +y).
double basis(int l, int m, double theta, double phi);

// Every y_i for i < bands^2 at a unit direction (SH frame), into out[0 .. bands^2).
void basis_all(int bands, const glm::dvec3& direction, std::span<double> out);

}  // namespace sh
