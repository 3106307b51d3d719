#pragma once
// A library model's named intermediate quantities (N, L, N·L, D, F, G, ...; docs/models.md,
// "Named quantities") at chosen pixels of its per-pixel render, for matching a shader's
// intermediate values against the model's by value: the first line of a shader that
// computes nothing the model computes is where it parts from the model.
#include <expected>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "reference/Reference.h"

namespace reference {

struct NamedQuantity {
  std::string name;
  std::vector<double> values;  // 1 value (a scalar) or 3 (a vector or a colour)
};

// The named quantities of `model` at each of `pixels` (x, y; row 0 at the top) of
// render(scene, model, Mode::per_pixel, params, perturbation): the same surface point,
// normal and lighting the render shades there (ambient and the scene light as render()
// applies them), in the order the model computes them, the last one "colour", bit for bit
// the render's pixel. First come the pixel's inputs: "P", "N interpolated" (the normal as
// interpolated, before normalisation), "T", "eye_position", "light_position",
// "light_vector". Vectors are given in object space (as the models compute) and each
// right after it in world space, named "<name> world" (directions and normals turned by
// the world matrix (normals by its inverse transpose) with their length kept, positions
// and differences of positions (light_position−P) transformed; under a similarity world matrix
// that is what a world-space shader computes). Colours have no world version. A pixel the
// mesh does not cover gets an empty list. Errors: render()'s, and a pixel outside the image.
std::expected<std::vector<std::vector<NamedQuantity>>, std::string> model_quantities(
    const Scene& scene, const std::string& model, const Params& params, std::span<const std::pair<int, int>> pixels,
    const Perturbation& perturbation = {});

}  // namespace reference
