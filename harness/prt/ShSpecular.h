#pragma once
// sh_specular's environment (book Ch. 9.7, "Simple specular highlights"): the SH diffuse
// plus a cube map, a darkened and blurred "specular view" of the light, looked up at the
// reflection vector. Here the specular view is analytic, so the references evaluate it
// exactly where the GPU samples the texture:
//   spec(ω) = k max(0, ω·s)^p     (s the light's direction, k `specular_scale`, p `specular_power`)
// generated on the CPU as an rgba32_float cube map of `cube_size`² texels per face, and
// the bound on what the GPU's seamless bilinear filter adds (the case's tolerance).
#include <string>

#include <glm/glm.hpp>

#include "pipeline/Texture.h"

namespace shaderbed {

struct SpecularLobe {
  glm::dvec3 axis{0, 1, 0};   // unit, in the scene (object) frame
  double power = 32;
  double scale = 0.5;
  // k max(0, ω·s)^p of a unit direction.
  double operator()(const glm::dvec3& unit_direction) const;
};

// The direction (not unit) of cube face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z) at face
// coordinates a = sc/|ma|, b = tc/|ma| in [-1, 1], by the Vulkan and GL face selection
// rules (major axis ma; sc, tc per face): a texel (i, j) of an N² face, row j, has its
// centre at a = 2(i + ½)/N − 1, b = 2(j + ½)/N − 1. Values past ±1 continue the face's plane.
glm::dvec3 cube_direction(int face, double a, double b);

// The lobe sampled at every texel centre, grey in RGB, alpha 1: faces in Texture's order.
Texture specular_cube(const SpecularLobe& lobe, int size);

// How far the GPU's seamless bilinear lookup of `cube` (specular_cube(lobe, N)) can be
// from the lobe itself, at any direction: the bilinear error on a face's texel grid,
// extended half a texel past its edges, (Δ²/8)(max|f_aa| + max|f_bb|) with Δ = 2/N the
// texel pitch in face coordinates, plus, where a footprint reaches past the edge, the
// difference between the texel the filter fetches (the neighbour face's edge texel, or
// the mean of the three corner texels) and the lobe at the position it is weighted as.
struct CubeFilterBound {
  double max_abs = 0;
  double bilinear = 0;   // the first term
  double seams = 0;      // the second
  std::string derivation;
};
CubeFilterBound cube_filter_bound(const SpecularLobe& lobe, int size);

}  // namespace shaderbed
