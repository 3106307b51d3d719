#pragma once
// The GLUT test-bed shapes (glutSolidSphere/Cube/Cone/Torus) with GLUT's parameters and
// orientation (axis along +z), smooth normals, tangents along u, UVs, and vertex colours
// from the normals, (0.5 + 0.5 n, 1).
//
// Counts, so tests and reports can state them:
//   sphere(slices, stacks):  (slices+1)(stacks+1) vertices, 2*slices*(stacks-1) triangles
//   cube(size, n):           6(n+1)^2 vertices,              12 n^2 triangles (GLUT: n = 1)
//   cone(slices, stacks):    (slices+2) + (slices+1)(stacks+1) vertices, 2*slices*stacks triangles
//   torus(sides, rings):     (sides+1)(rings+1) vertices,    2*sides*rings triangles
#include <optional>
#include <string>
#include <vector>

#include "pipeline/Mesh.h"

namespace shaderbed {

Mesh solid_sphere(float radius, int slices, int stacks);
Mesh solid_cube(float size, int subdivisions = 1);
Mesh solid_cone(float base, float height, int slices, int stacks);
Mesh solid_torus(float inner_radius, float outer_radius, int sides, int rings);

enum class Tessellation { low, high };

// The shaderbed scene's shapes at the size the book's camera frames well.
std::optional<Mesh> make_shape(const std::string& name, Tessellation tessellation);
// The same shapes at any density, for tessellation sweeps: sphere and cone with `slices`
// slices and slices/2 stacks, torus with slices/2 sides and `slices` rings, cube with
// slices/8 subdivisions per edge (at least 1). slices >= 4.
std::optional<Mesh> make_shape(const std::string& name, int slices);
const std::vector<std::string>& shape_names();   // sphere, cube, cone, torus

}  // namespace shaderbed
