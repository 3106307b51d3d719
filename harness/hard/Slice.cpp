#include "hard/Slice.h"

#include <cmath>
#include <numbers>

#include <glm/gtc/type_ptr.hpp>

namespace shaderbed::hard {
namespace {

constexpr double pi = std::numbers::pi;

// A unit vector perpendicular to `axis`, toward `hint` when it is not along the axis.
glm::dvec3 perpendicular(const glm::dvec3& axis, const glm::dvec3& hint) {
  glm::dvec3 p = hint - axis * glm::dot(axis, hint);
  if (glm::dot(p, p) < 1e-20) {
    const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    p = other - axis * glm::dot(axis, other);
  }
  return glm::normalize(p);
}

glm::dvec3 uniform3(const NamedValues& u, const char* name) {
  const std::vector<double>& v = u.at(name);
  return {v[0], v[1], v[2]};
}

std::vector<double> floats4(const glm::dvec3& v, double w) { return {v.x, v.y, v.z, w}; }

}  // namespace

const char* to_string(NormalLayout l) {
  switch (l) {
    case NormalLayout::sphere: return "sphere";
    case NormalLayout::lobe: return "lobe";
    case NormalLayout::half_angle: return "half_angle";
    case NormalLayout::plane: return "plane";
  }
  return "?";
}

Slice make_slice(const SliceSpec& spec, int size) {
  Slice s;
  s.spec = spec;
  s.width = s.height = size | 1;
  const int w = s.width, h = s.height;
  const glm::dvec3 v = glm::normalize(spec.to_eye);
  const glm::dvec3 l = glm::normalize(spec.to_light);
  // Sphere frame: e3 = V, e1 toward L's projection, e2 = e3 x e1.
  const glm::dvec3 e1 = perpendicular(v, l), e2 = glm::cross(v, e1);
  // Lobe frame around H (H undefined for L = -V: take V).
  const glm::dvec3 sum = l + v;
  const glm::dvec3 half = glm::dot(sum, sum) > 1e-20 ? glm::normalize(sum) : v;
  const glm::dvec3 h1 = perpendicular(half, l), h2 = glm::cross(half, h1);
  // Half-angle map: N turns from H toward B, perpendicular to the L-V plane.
  const glm::dvec3 across = perpendicular(half, glm::cross(l, v));
  const glm::dvec3 plane_n = glm::normalize(spec.plane_normal);
  const glm::dvec3 plane_t = perpendicular(plane_n, glm::dvec3(1, 0, 0));

  s.pixels.resize(size_t(w) * h);
  s.mesh.name = std::string("slice-") + to_string(spec.layout);
  s.mesh.vertices.reserve(s.pixels.size() * 4);
  s.mesh.indices.reserve(s.pixels.size() * 6);
  const double sx = 2.0 / w, sy = 2.0 / h;   // pixel size in clip space
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      SlicePixel& p = s.pixels[size_t(y) * w + x];
      glm::dvec3 n, t;
      switch (spec.layout) {
        case NormalLayout::sphere: {
          p.polar = pi * y / (h - 1);
          p.azimuth = -pi + 2 * pi * x / (w - 1);
          const glm::dvec3 radial = std::cos(p.azimuth) * e1 + std::sin(p.azimuth) * e2;
          n = std::sin(p.polar) * radial + std::cos(p.polar) * v;
          t = -std::sin(p.azimuth) * e1 + std::cos(p.azimuth) * e2;   // along increasing azimuth, perpendicular to N
          break;
        }
        case NormalLayout::lobe: {
          const double k = std::tan(spec.lobe_radius);
          const double u = k * (2.0 * x / (w - 1) - 1), vv = k * (1 - 2.0 * y / (h - 1));
          n = glm::normalize(half + u * h1 + vv * h2);
          t = perpendicular(n, h1);
          break;
        }
        case NormalLayout::half_angle:
          p.half_angle = kMinHalfAngle * std::pow(kMaxHalfAngle / kMinHalfAngle, double(x) / (w - 1));
          n = std::cos(p.half_angle) * half + std::sin(p.half_angle) * across;
          t = perpendicular(n, h1);
          break;
        case NormalLayout::plane:
          n = plane_n;
          t = plane_t;
          break;
      }
      p.claimed_normal = n;
      double length = 1;
      if (spec.long_normals) length += std::pow(10.0, -6 + (x + y) % 3);
      p.normal = glm::vec3(n * length);
      switch (spec.tangents) {
        case TangentLayout::perpendicular: p.tangent = glm::vec3(t); break;
        case TangentLayout::zero: p.tangent = glm::vec3(0); break;
        case TangentLayout::parallel: p.tangent = glm::vec3(n); break;
      }

      // The quad covering the pixel; its centre is the pixel centre.
      const double cx = -1 + sx * (x + 0.5), cy = 1 - sy * (y + 0.5);
      p.position = kGridHalfSize * glm::dvec3(cx, cy, 0);
      const uint32_t first = uint32_t(s.mesh.vertices.size());
      for (const auto& [dx, dy] : {std::pair{-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}}) {
        const glm::vec3 corner(kGridHalfSize * glm::dvec3(cx + dx * sx, cy + dy * sy, 0));
        s.mesh.vertices.push_back({corner, p.normal, p.tangent, glm::vec2(0)});
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) s.mesh.indices.push_back(first + i);
    }
  fill_binormals(s.mesh.vertices);

  if (spec.layout == NormalLayout::half_angle)
    for (int y = 0; y < h; ++y)
      s.row_values.push_back(spec.row_first * std::pow(spec.row_last / spec.row_first, double(y) / (h - 1)));

  // clip = (x / g, y / g, 0.5, 1): the grid fills the screen at depth 0.5.
  glm::dmat4 transform(1.0);
  transform[0][0] = transform[1][1] = 1 / kGridHalfSize;
  transform[2][2] = 0;
  transform[3][2] = 0.5;
  const double* m = glm::value_ptr(transform);
  s.uniforms["transform"] = std::vector<double>(m, m + 16);
  const glm::dmat4 identity(1.0);   // a named matrix: value_ptr must not point into a temporary
  const double* world = glm::value_ptr(identity);
  s.uniforms["world"] = std::vector<double>(world, world + 16);
  s.uniforms["eye_position"] = floats4(kEyeDistance * v, 1);
  if (spec.layout == NormalLayout::plane) {
    // The spot (and Warn light) shines along -light_vector = -N: the centre pixel is on its axis.
    s.uniforms["light_vector"] = floats4(plane_n, 0);
    s.uniforms["light_position"] = floats4(spec.light_height * plane_n, 1);
  } else {
    s.uniforms["light_vector"] = floats4(l, 0);
    s.uniforms["light_position"] = floats4(spec.light_at_eye ? kEyeDistance * v : kLightDistance * l, 1);
  }
  return s;
}

NamedValues slice_scene_values(const Slice& slice, const glm::dvec3& ambient) {
  NamedValues out;
  const std::vector<double>& t = slice.uniforms.at("transform");
  glm::dmat4 transform;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) transform[c][r] = t[size_t(c * 4 + r)];
  // Every vertex has z = 0, so a unit z scale draws the same and makes the matrix invertible.
  glm::dmat4 invertible = transform;
  invertible[2][2] = 1;
  const glm::dmat4 identity(1.0);
  const auto add = [&](const std::string& name, const glm::dmat4& m, const glm::dmat4& for_inverse) {
    const auto put = [&](const std::string& n, const glm::dmat4& v) {
      const double* p = glm::value_ptr(v);
      out[n] = std::vector<double>(p, p + 16);
    };
    put(name, m);
    put(name + "_inverse", glm::inverse(for_inverse));
    put(name + "_transpose", glm::transpose(m));
    put(name + "_inverse_transpose", glm::transpose(glm::inverse(for_inverse)));
  };
  for (const char* name : {"world", "view", "world_view"}) add(name, identity, identity);
  for (const char* name : {"projection", "view_projection", "transform"}) add(name, transform, invertible);
  const glm::dmat3 identity3(1.0);
  const double* n = glm::value_ptr(identity3);
  out["normal_matrix"] = out["normal_matrix_view"] = std::vector<double>(n, n + 9);
  for (const char* suffix : {"", "_world", "_view"})
    for (const char* name : {"light_vector", "light_position", "eye_position"})
      out[std::string(name) + suffix] = slice.uniforms.at(name);
  out["ambient_light"] = {ambient.x, ambient.y, ambient.z, 1.0};
  return out;
}

reference::Configuration pixel_configuration(const Slice& slice, const SlicePixel& pixel, bool point_light,
                                             const glm::dvec3* at) {
  const glm::dvec3 position = at ? *at : pixel.position;
  reference::Configuration c;
  c.normal = glm::dvec3(pixel.normal);
  c.tangent = glm::dvec3(pixel.tangent);
  c.to_eye = uniform3(slice.uniforms, "eye_position") - position;
  const glm::dvec3 light_vector = uniform3(slice.uniforms, "light_vector");
  if (point_light) {
    const glm::dvec3 to_light = uniform3(slice.uniforms, "light_position") - position;
    c.distance = glm::length(to_light);
    c.to_light = to_light;
    c.spot_axis = -light_vector;
  } else {
    c.to_light = light_vector;
  }
  return c;
}

std::map<std::string, std::vector<double>> row_params(const Slice& slice, int y,
                                                      std::map<std::string, std::vector<double>> params) {
  if (slice.row_values.empty()) return params;
  std::vector<double>& value = params[slice.spec.row_param];
  if (value.empty()) value.resize(1);
  for (double& component : value) component = slice.row_values[size_t(y)];
  return params;
}

Mesh row_mesh(const Slice& slice, int y) {
  Mesh row;
  row.name = slice.mesh.name + "-row";
  const size_t first = size_t(y) * slice.width * 4, count = size_t(slice.width) * 4;
  row.vertices.assign(slice.mesh.vertices.begin() + first, slice.mesh.vertices.begin() + first + count);
  for (uint32_t q = 0; q < uint32_t(slice.width); ++q)
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) row.indices.push_back(q * 4 + i);
  return row;
}

}  // namespace shaderbed::hard
