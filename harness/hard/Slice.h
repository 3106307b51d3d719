#pragma once
// A parameter-space slice: a full-screen grid where every pixel is one shading
// configuration, drawn as one tiny flat quad per pixel (the same normal and tangent at
// its four vertices, so interpolation returns them unchanged) with the case's own
// shaders. An orthographic "transform" maps the quad grid onto the screen; the grid is
// tiny in object space (kGridHalfSize) and the eye far away (kEyeDistance) along the
// slice's V, so V is the same for every pixel to ~2e-7 rad; L is the light_vector
// uniform. The per-pixel configuration the GPU sees (the float inputs) is kept so the
// reference evaluates exactly that configuration.
//
// Layouts of the normals:
//  - sphere: the whole sphere of normals, equirectangular about V: row y is the polar
//    angle from V, 0 (top row, N = V) to pi (bottom row, N = -V), in (height - 1) equal
//    steps; column x the azimuth about V, -pi to pi in (width - 1) steps, 0 (the centre
//    column) on L's side of V. The size is made odd, so the polar angles 0, pi/4, pi/2,
//    3pi/4, pi and the azimuths 0, +-pi/2, +-pi fall on pixel centres when (size-1) is a
//    multiple of 4 (e.g. 129). One image holds N·L < 0, N·V -> 0, N = V, N·H = 0, ...
//  - lobe: normals in a small cone around H = normalize(L + V) (gnomonic: pixel offsets
//    are tangents of the angle from H, up to lobe_radius at the edge mid-points), the
//    centre pixel exactly H: the peak of a sharp specular lobe.
//  - half_angle: a map of a lobe against a parameter: column x is the angle between N and
//    H, log-spaced from kMinHalfAngle (left) to kMaxHalfAngle (right), N turning away from
//    H across the L-V plane (so N.L = N.V stay equal and positive); row y is the value of
//    the case parameter `row_param`, log-spaced from row_first (top) to row_last
//    (bottom). The runner draws the slice a row at a time, each with its row's value.
//  - plane: one normal for every pixel and a point light at light_height above the
//    centre pixel along N (shining along -N for spot and Warn): the distance to the light
//    runs from light_height at the centre to ~kGridHalfSize at the corners.
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "reference/Reference.h"
#include "pipeline/Mesh.h"
#include "scene/Scene.h"

namespace shaderbed::hard {

constexpr double kGridHalfSize = 1.0 / 1024;   // object-space half width of the grid
constexpr double kEyeDistance = 8192;           // eye position = kEyeDistance * V
constexpr double kLightDistance = 50;           // sphere/lobe: point light at 50 L, as the book's scene

constexpr double kMinHalfAngle = 1e-5;          // half_angle: radians from H at the left column
constexpr double kMaxHalfAngle = 1.5;           // and at the right one

enum class NormalLayout { sphere, lobe, half_angle, plane };
// The tangent attribute: perpendicular to N (unit), zero, or along N (a degenerate frame).
enum class TangentLayout { perpendicular, zero, parallel };
const char* to_string(NormalLayout);

struct SliceSpec {
  glm::dvec3 to_light{1, 0, 0};    // nominal L (normalised by make_slice)
  glm::dvec3 to_eye{0, 0, 1};      // nominal V
  NormalLayout layout = NormalLayout::sphere;
  double lobe_radius = 0.01;       // lobe: angle from H at the edge mid-points, radians
  bool long_normals = false;       // normal attributes 1 + {1e-6, 1e-5, 1e-4} long, by (x + y) mod 3
  std::string row_param;           // half_angle: the case parameter that changes down the rows
  double row_first = 1, row_last = 1;
  glm::dvec3 plane_normal{0, 0, 1};
  double light_height = 1e-6;      // plane: light above the centre pixel; 0 puts it on the surface
  bool light_at_eye = false;       // sphere, lobe: the point light at the eye position (L = V)
  TangentLayout tangents = TangentLayout::perpendicular;
};

struct SlicePixel {
  glm::dvec3 claimed_normal;       // unit, in double, before rounding to float
  double polar = 0;                // sphere: angle between N and V
  double azimuth = 0;              // sphere: azimuth of N about V, 0 on L's side
  double half_angle = 0;           // half_angle: angle between N and H
  glm::vec3 normal;                // the vertex attribute (length 1, or 1 + eps)
  glm::vec3 tangent;               // unit, perpendicular to the claimed normal
  glm::dvec3 position;             // pixel centre, object space
};

struct Slice {
  SliceSpec spec;
  int width = 0, height = 0;
  Mesh mesh;                       // 4 vertices, 2 triangles per pixel, row-major from the top
  NamedValues uniforms;            // transform, world, light_vector, eye_position, light_position
  std::vector<SlicePixel> pixels;  // width * height, row 0 = top
  std::vector<double> row_values;  // half_angle: spec.row_param's value per row; empty otherwise
};

// `size` is the requested width and height; it is rounded up to an odd number.
Slice make_slice(const SliceSpec& spec, int size);

// Every scene quantity (scene/Scene.h) as the slice sets it: world and view the identity,
// projection the slice's orthographic transform, object = world = view space, the eye, the
// lights and `ambient` as the slice and case give them. A user's shader may bind any of
// them ("view", "normal_matrix", "light_position_world", ...).
NamedValues slice_scene_values(const Slice& slice, const glm::dvec3& ambient);

// The configuration the GPU evaluates at a pixel, from the float uniforms and attributes
// (in double): V from the eye position to the pixel centre, L the light_vector (or, for
// point lights, toward light_position with its distance), N and T the attributes.
// `at` replaces the pixel centre (per-vertex variants shade the quad's corners).
reference::Configuration pixel_configuration(const Slice& slice, const SlicePixel& pixel, bool point_light,
                                             const glm::dvec3* at = nullptr);

// The case parameters at row y: `params` with the slice's row parameter set to that row's
// value in every component (roughness_xy = (v, v)); `params` itself without a row parameter.
std::map<std::string, std::vector<double>> row_params(const Slice& slice, int y,
                                                      std::map<std::string, std::vector<double>> params);

// The part of the slice's mesh that covers row y (the runner draws half_angle slices a
// row at a time).
Mesh row_mesh(const Slice& slice, int y);

}  // namespace shaderbed::hard
