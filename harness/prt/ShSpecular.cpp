#include "prt/ShSpecular.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace shaderbed {
namespace {

// The face whose major axis a direction has (ties: the first axis).
int major_face(const glm::dvec3& d) {
  const glm::dvec3 m = glm::abs(d);
  const int axis = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
  return 2 * axis + (d[axis] < 0 ? 1 : 0);
}

// The inverse of cube_direction on `face`: (sc/|ma|, tc/|ma|).
glm::dvec2 face_coordinates(int face, const glm::dvec3& d) {
  switch (face) {
    case 0: return glm::dvec2(-d.z, -d.y) / std::abs(d.x);
    case 1: return glm::dvec2(d.z, -d.y) / std::abs(d.x);
    case 2: return glm::dvec2(d.x, d.z) / std::abs(d.y);
    case 3: return glm::dvec2(d.x, -d.z) / std::abs(d.y);
    case 4: return glm::dvec2(d.x, -d.y) / std::abs(d.z);
    default: return glm::dvec2(-d.x, -d.y) / std::abs(d.z);
  }
}

}  // namespace

double SpecularLobe::operator()(const glm::dvec3& unit_direction) const {
  return scale * std::pow(std::max(0.0, glm::dot(unit_direction, axis)), power);
}

glm::dvec3 cube_direction(int face, double a, double b) {
  switch (face) {
    case 0: return {1, -b, -a};    // +X: sc = -rz, tc = -ry
    case 1: return {-1, -b, a};    // -X: sc = +rz, tc = -ry
    case 2: return {a, 1, b};      // +Y: sc = +rx, tc = +rz
    case 3: return {a, -1, -b};    // -Y: sc = +rx, tc = -rz
    case 4: return {a, -b, 1};     // +Z: sc = +rx, tc = -ry
    default: return {-a, -b, -1};  // -Z: sc = -rx, tc = -ry
  }
}

Texture specular_cube(const SpecularLobe& lobe, int size) {
  Texture t;
  t.name = "sh_specular";
  t.dimensions = 2;
  t.width = t.height = uint32_t(size);
  t.format = TexelFormat::rgba32_float;
  t.cube = true;
  t.texels.reserve(size_t(6) * size_t(size) * size_t(size) * 4);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double a = 2.0 * (i + 0.5) / size - 1.0, b = 2.0 * (j + 0.5) / size - 1.0;
        const float v = float(lobe(glm::normalize(cube_direction(face, a, b))));
        t.texels.insert(t.texels.end(), {v, v, v, 1.0f});
      }
  return t;
}

CubeFilterBound cube_filter_bound(const SpecularLobe& lobe, int size) {
  const double pitch = 2.0 / size;   // Δ, between texel centres in face coordinates
  const auto f = [&](int face, double a, double b) { return lobe(glm::normalize(cube_direction(face, a, b))); };

  // Bilinear interpolation of f at the texel centres errs by at most
  // (Δ²/8) max|f_aa| + (Δ²/8) max|f_bb| over the cell: f - I_a I_b f = (f - I_a f) + I_a (f - I_b f).
  // The second derivatives by central differences (step e: truncation e² f''''/12 and
  // rounding 1e-16 f/e², both far below f''), sampled 4 times per texel on each axis,
  // over the face extended half a texel past its edges (a footprint's outer taps).
  const double e = 1e-3, reach = 1.0 + pitch / 2;
  const int samples = 4 * size + 1;
  double f_aa = 0, f_bb = 0;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < samples; ++y)
      for (int x = 0; x < samples; ++x) {
        const double a = -reach + 2 * reach * x / (samples - 1), b = -reach + 2 * reach * y / (samples - 1);
        const double c = f(face, a, b);
        f_aa = std::max(f_aa, std::abs(f(face, a + e, b) - 2 * c + f(face, a - e, b)) / (e * e));
        f_bb = std::max(f_bb, std::abs(f(face, a, b + e) - 2 * c + f(face, a, b - e)) / (e * e));
      }
  CubeFilterBound out;
  out.bilinear = pitch * pitch / 8 * (f_aa + f_bb);

  // Seamless filtering: a tap past the face's edge (texel i = -1 or N, weighted as if at
  // a = ∓(1 + Δ/2)) fetches the neighbour face's edge texel with the same index along the
  // edge, whose centre is elsewhere (the two faces' texel rows fan apart away from the
  // edge's middle: a first-order displacement, up to Δ/2 at the corners); a tap past a
  // corner fetches the three corner texels' mean (or, on some implementations, one of
  // them). Each such tap adds its weight times |fetched - f(where it is weighted)|: a
  // sample lies on its own face, so an edge tap weighs at most ½ and a corner tap ¼ (with
  // the two edge taps beside it at most ¼ each).
  const double inner = 1.0 - pitch / 2;
  double edge = 0, corner = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = -1; j <= size; ++j)
      for (int i = -1; i <= size; ++i) {
        const bool out_i = i < 0 || i >= size, out_j = j < 0 || j >= size;
        if (!out_i && !out_j) continue;
        const double a = 2.0 * (i + 0.5) / size - 1.0, b = 2.0 * (j + 0.5) / size - 1.0;
        const double weighted_as = f(face, a, b);
        std::vector<double> fetched;
        if (out_i && out_j) {
          // The cube's corner and the corner texel of each of its three faces.
          const glm::dvec3 corner = cube_direction(face, a < 0 ? -1 : 1, b < 0 ? -1 : 1);
          for (int axis = 0; axis < 3; ++axis) {
            const int other = 2 * axis + (corner[axis] < 0 ? 1 : 0);
            const glm::dvec2 at = face_coordinates(other, corner) * inner;
            fetched.push_back(f(other, at.x, at.y));
          }
          double mean = 0;
          for (double v : fetched) mean += v / 3;
          fetched.push_back(mean);
        } else {
          // The neighbour is the face the tap's position lies on; the point on the shared
          // edge has one coordinate ±1 on it, the texel is half a texel inside.
          const int other = major_face(cube_direction(face, a, b));
          glm::dvec2 at = face_coordinates(other, cube_direction(face, std::clamp(a, -1.0, 1.0), std::clamp(b, -1.0, 1.0)));
          const int across = std::abs(at.x) > std::abs(at.y) ? 0 : 1;
          at[across] = at[across] < 0 ? -inner : inner;
          fetched.push_back(f(other, at.x, at.y));
        }
        double& worst = out_i && out_j ? corner : edge;
        for (double v : fetched) worst = std::max(worst, std::abs(v - weighted_as));
      }
  out.seams = std::max(edge / 2, (2 * edge + corner) / 4);
  out.max_abs = out.bilinear + out.seams;
  out.derivation = fmt::format(
      "seamless bilinear lookup of {}² texels per face: (Δ²/8)(max|f_aa| + max|f_bb|) = {:.3g} "
      "(Δ = 2/{}, max|f_aa| = {:.3g}, max|f_bb| = {:.3g} in face coordinates) + taps across edges and corners {:.3g} "
      "(max(e/2, (2e + c)/4), e = {:.3g} at an edge tap, c = {:.3g} at a corner tap)",
      size, out.bilinear, size, f_aa, f_bb, out.seams, edge, corner);
  return out;
}

}  // namespace shaderbed
