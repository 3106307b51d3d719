#pragma once
// `shaderbed sh project`: a light's SH coefficients by the book's jittered projection
// beside the exact ones (closed forms, or Gauss-Legendre for a map), and the book's test
// function with the values its Fig. 8.14 table prints.
#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sh/Sampling.h"

namespace shaderbed {

struct ShProjectionRequest {
  std::string light = "book";   // book (the test function), directional, cone, sky or probe
  std::string probe, mapping = "latlong";   // the environment map of `probe`, latlong or angular
  int bands = 5, grid = 100;    // grid x grid jittered samples
  uint64_t seed = sh::default_seed;
  std::vector<double> direction{0, 1, 0};   // toward the directional or cone light, in the scene (y up)
  double radius = 0.6;          // the cone's half-angle
  bool exact_only = false;      // no jittered projection
};

struct ShProjection {
  struct Largest {
    double value = 0;
    size_t i = 0;   // the coefficient where it is
  };
  ShProjectionRequest request;
  std::string description, exact_method;
  bool scalar = false;         // the book's test function: scalar coefficients, else RGB
  bool has_jittered = false;   // not with exact_only, nor for a delta light
  std::vector<double> jittered_scalar, exact_scalar;
  std::vector<glm::dvec3> jittered_rgb, exact_rgb;
  std::vector<double> book;    // the book's printed values of the first coefficients (its test function)
  Largest jittered_vs_exact, book_vs_exact, book_vs_jittered;
};

// An error is bad input: a light that cannot be made, a probe missing or unreadable (naming the file).
std::expected<ShProjection, std::string> project_sh_light(const ShProjectionRequest& request);

}  // namespace shaderbed
