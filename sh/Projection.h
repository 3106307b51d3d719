#pragma once
// Projection of functions on the sphere onto the SH basis (Eq. 10, 16), reconstruction
// (Eq. 11) and the coefficient arithmetic of 8.2.3: sums of lights, and the product
// integral of two band-limited functions as a dot product (Eq. 18).
// Scalar coefficients are std::vector<double>, RGB ones std::vector<glm::dvec3>, both of
// size bands^2 in the order i = l(l+1) + m. Directions are in the SH frame.
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Sampling.h"

namespace sh {

using ScalarFunction = std::function<double(const glm::dvec3&)>;
using RgbFunction = std::function<glm::dvec3(const glm::dvec3&)>;

// c_i = sum_s weight_s f(d_s) y_i(d_s) over the set's samples, for its bands (Eq. 16 with
// the set's weights: 4 pi / N for the jittered grid).
std::vector<double> project(const ScalarFunction& f, const SampleSet& samples);
std::vector<glm::dvec3> project_rgb(const RgbFunction& f, const SampleSet& samples);
// The same onto the first `bands` bands only (at most the set's: more are clamped to it).
std::vector<double> project(const ScalarFunction& f, const SampleSet& samples, int bands);
std::vector<glm::dvec3> project_rgb(const RgbFunction& f, const SampleSet& samples, int bands);

// Exact projection of a zonal function, one with rotational symmetry about `axis`:
// f(w) = g(w . axis) where w . axis >= t0, 0 elsewhere. c_lm = 2 pi G_l y_lm(axis) with
// G_l = integral of g(t) P_l(t) over [t0, 1], computed by Gauss-Legendre on that interval:
// exact (to rounding) when g is a polynomial of degree <= `degree`.
std::vector<double> project_zonal(int bands, const glm::dvec3& axis, const std::function<double(double)>& g, double t0,
                                  int degree);
// The Legendre moments G_l (l < bands) of that profile.
std::vector<double> zonal_moments(int bands, const std::function<double(double)>& g, double t0, int degree);

// f~(d) = sum_i c_i y_i(d) (Eq. 11), over the complete bands in `coefficients`.
double evaluate(std::span<const double> coefficients, const glm::dvec3& direction);
glm::dvec3 evaluate(std::span<const glm::dvec3> coefficients, const glm::dvec3& direction);

// a + b; a shorter vector counts as zero in the bands it lacks (lights of different orders add).
std::vector<double> add(std::span<const double> a, std::span<const double> b);
std::vector<glm::dvec3> add(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b);
// s * a.
std::vector<double> scale(std::span<const double> a, double s);
std::vector<glm::dvec3> scale(std::span<const glm::dvec3> a, const glm::dvec3& s);

// sum_i a_i b_i over the common length: the integral of the product of the two band-limited
// functions (Eq. 18); bands only one side has contribute nothing, by orthogonality.
double dot(std::span<const double> a, std::span<const double> b);
// Per channel, as the book's SHLighting (RGB light with RGB transfer, or with a scalar one).
glm::dvec3 dot(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b);
glm::dvec3 dot(std::span<const glm::dvec3> a, std::span<const double> b);

}  // namespace sh
