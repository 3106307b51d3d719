#pragma once
// An independent evaluation of docs/models.md in 50 significant digits
// (boost::multiprecision::cpp_bin_float_50), for the oracle tests. It shares nothing with
// reference/ but the model names and parameter defaults: it is written from the
// documented equations as printed (1 - (N·H)², acos(N·H), A d² + B d + C, normalize),
// because with 50 digits and an exponent range of ±2^31 those literal forms neither
// cancel to below 1e-12 nor under/overflow. Directions given as doubles (N, the
// directional L, V from the eye) are taken as the directions they point in: normalised
// here, in 50 digits.
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "reference/LightingModel.h"
#include "reference/Reference.h"

namespace reference::oracle {

using Real = boost::multiprecision::cpp_bin_float_50;
using Colour = std::array<Real, 3>;

struct Vec {
  Real x, y, z;
};

inline Vec exact(const glm::dvec3& v) { return {Real(v.x), Real(v.y), Real(v.z)}; }
inline Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator-(const Vec& a) { return {-a.x, -a.y, -a.z}; }
inline Vec operator*(const Vec& a, const Real& s) { return {a.x * s, a.y * s, a.z * s}; }
inline Real dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(const Vec& a, const Vec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real norm(const Vec& a) { return sqrt(dot(a, a)); }
inline Vec normalize(const Vec& a) { return a * (Real(1) / norm(a)); }
inline bool is_zero(const Vec& a) { return a.x == 0 && a.y == 0 && a.z == 0; }

inline Real sat(const Real& x) { return x > 0 ? x : Real(0); }
inline Real clamp1(const Real& x) { return x > 1 ? Real(1) : x < -1 ? Real(-1) : x; }
// b^n with C's pow conventions at b = 0.
inline Real power(const Real& b, const Real& n) {
  if (b == 0) return n == 0 ? Real(1) : n > 0 ? Real(0) : std::numeric_limits<Real>::infinity();
  return pow(b, n);
}

// What a model is given, exactly: the surface point and the object-space lights.
struct Inputs {
  Vec position, normal, tangent;
  Vec light_direction, light_position, eye_position;
};

inline Inputs exact(const SurfacePoint& point, const ObjectSpaceLighting& lighting) {
  return {exact(point.position),           exact(point.normal),         exact(point.tangent),
          exact(lighting.light_direction), exact(lighting.light_position), exact(lighting.eye_position)};
}

// reference::evaluate()'s placement (Reference.h, Configuration), done exactly: L, V, N and
// the spot axis normalised in 50 digits, the point light at distance · L, the eye at V.
inline Inputs exact(const Configuration& c, bool spot_light) {
  const Vec L = normalize(exact(c.to_light)), V = normalize(exact(c.to_eye)), N = normalize(exact(c.normal));
  const Vec axis = c.spot_axis ? normalize(exact(*c.spot_axis)) : -N;
  return {Vec{}, N, exact(c.tangent), spot_light ? -axis : L, L * Real(c.distance), V};
}

struct Parameters {
  const Params& params;
  Real scalar(const std::string& name, int i = 0) const { return Real(params.at(name).at(i)); }
};

// docs/models.md's colour for `model`; nullopt where the model is undefined (a point light
// at distance 0).
inline std::optional<Colour> evaluate(const std::string& model, const Params& all, const Inputs& in) {
  const Parameters p{all};
  const auto colour = [&](const std::string& name) { return Colour{p.scalar(name, 0), p.scalar(name, 1), p.scalar(name, 2)}; };
  const auto scaled = [](const Colour& c, const Real& s) { return Colour{c[0] * s, c[1] * s, c[2] * s}; };
  const auto product = [](const Colour& a, const Colour& b) { return Colour{a[0] * b[0], a[1] * b[1], a[2] * b[2]}; };
  const auto sum = [](const Colour& a, const Colour& b) { return Colour{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; };
  const Real pi = boost::math::constants::pi<Real>();

  const Vec N = normalize(in.normal);
  const Vec L = normalize(in.light_direction);
  const Vec V = normalize(in.eye_position - in.position);
  const Real NL = dot(N, L), NV = dot(N, V);
  const auto reflected = [&] { return normalize(N * (2 * NL) - L); };

  if (model == "ambient") return colour("ambient");
  if (model == "lambert") return scaled(colour("diffuse"), sat(NL));
  if (model == "phong" || model == "schlick") {
    const Real t = sat(dot(reflected(), V)), n = p.scalar("power");
    const Real spec = model == "phong" ? power(t, n) : t / (n - (n - 1) * t);
    return sum(scaled(colour("diffuse"), sat(NL)), scaled(colour("specular"), spec));
  }
  if (model == "blinn_phong") {
    // H undefined where L + V = 0: docs/errata.md takes N·H = 0 there.
    const Vec s = L + V;
    const Real NH = is_zero(s) ? Real(0) : dot(N, normalize(s));
    return sum(scaled(colour("diffuse"), sat(NL)), scaled(colour("specular"), power(sat(NH), p.scalar("power"))));
  }
  if (model == "minnaert") {
    return scaled(colour("diffuse"), power(sat(NV) * sat(NL), p.scalar("minnaert_power")) * sat(NL));
  }
  if (model == "oren_nayar") {
    if (!(NL > 0)) return Colour{};
    const Real s = p.scalar("roughness_sq");
    const Real A = 1 - Real(0.5) * s / (s + Real(0.33)), B = Real(0.45) * s / (s + Real(0.09));
    const Real theta_r = acos(clamp1(NV)), theta_i = acos(clamp1(NL));
    const Real alpha = theta_i > theta_r ? theta_i : theta_r, beta = theta_i > theta_r ? theta_r : theta_i;
    const Vec eye_plane = V - N * NV, light_plane = L - N * NL;
    Real cos_c = 0;
    if (dot(eye_plane, eye_plane) >= Real(1e-12) && dot(light_plane, light_plane) >= Real(1e-12))
      cos_c = sat(dot(normalize(eye_plane), normalize(light_plane)));
    return scaled(colour("diffuse"), NL * (A + B * cos_c * sin(alpha) * tan(beta)));
  }
  if (model == "ward_iso" || model == "ward_aniso" || model == "cook_torrance") {
    const bool lit = NL > 0 && NV > 0;
    const Vec H = normalize(L + V);
    const Real NH = dot(N, H);
    if (model == "cook_torrance") {
      if (!lit) return Colour{};
      const Real c = p.scalar("gaussian_c"), m = p.scalar("slope_m"), r0 = p.scalar("fresnel_r0");
      const Real nh = sat(NH), VH = dot(V, H);
      const Real a = acos(clamp1(nh));
      const Real D = c * exp(-(a / m) * (a / m));
      Real G = 1;
      const Real g1 = 2 * nh * NV / VH, g2 = 2 * nh * NL / VH;
      if (g1 < G) G = g1;
      if (g2 < G) G = g2;
      if (G < 0) G = 0;
      const Real F = r0 + (1 - r0) * pow(1 - VH, 5);
      return scaled(colour("diffuse"), F * D * G / (NL * NV));
    }
    Colour spec{};
    if (lit && model == "ward_iso") {
      const Real sigma = p.scalar("roughness");
      const Real tan2 = (1 - NH * NH) / (NH * NH);
      spec = scaled(colour("specular"), exp(-tan2 / (sigma * sigma)) / (4 * pi * sigma * sigma) / sqrt(NL * NV));
    }
    if (lit && model == "ward_aniso") {
      const Real sx = p.scalar("roughness_xy", 0), sy = p.scalar("roughness_xy", 1);
      const Vec t = in.tangent - N * dot(N, in.tangent);
      // The frame is undefined only for T - N(N·T) = 0 (docs/errata.md); in 50 digits a
      // double T parallel to N leaves ~1e-50 of rounding.
      if (norm(t) > Real(1e-40) * norm(in.tangent)) {
        const Vec X = normalize(t), Y = cross(N, X);
        const Real hx = dot(H, X) / sx, hy = dot(H, Y) / sy;
        spec = scaled(colour("specular"), exp(-2 * (hx * hx + hy * hy) / (1 + NH)) / (4 * pi * sx * sy) / sqrt(NL * NV));
      }
    }
    return scaled(sum(colour("diffuse"), spec), sat(NL));
  }
  if (model == "point_attenuated" || model == "spot" || model == "warn") {
    const Vec to_light = in.light_position - in.position;
    if (is_zero(to_light)) return std::nullopt;  // d = 0: undefined
    const Real d = norm(to_light);
    const Vec Lp = to_light * (Real(1) / d);
    const Colour light = product(colour("diffuse"), colour("light_color"));
    const Real lambert = sat(dot(N, Lp));
    if (model == "warn") return scaled(light, lambert / (d * d) * power(sat(dot(Lp, L)), p.scalar("warn_exponent")));
    const Real falloff = p.scalar("attenuation", 0) * d * d + p.scalar("attenuation", 1) * d + p.scalar("attenuation", 2);
    Real s = 1;
    if (model == "spot") {
      const Real cos_theta = dot(Lp, L), umbra = p.scalar("cos_umbra"), penumbra = p.scalar("cos_penumbra");
      if (cos_theta >= umbra) s = 1;
      else if (cos_theta <= penumbra) s = 0;
      else s = power((cos_theta - penumbra) / (umbra - penumbra), p.scalar("falloff"));
    }
    return scaled(light, s * lambert / falloff);
  }
  return std::nullopt;
}

}  // namespace reference::oracle
