// The twin executing compiled GLSL, every pixel checked against the same computation done in C++.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spirv/unified1/spirv.hpp11>

#include "TwinTestSupport.h"

namespace twin_tests {
namespace {

using Pixel = std::array<double, 4>;
using PixelFunction = std::function<Pixel(double x, double y)>;   // from gl_FragCoord.xy

std::string fragment_shader(const std::string& declarations, const std::string& main_body) {
  return "#version 450\nlayout(location = 0) out vec4 colour;\n" + declarations + "\nvoid main() {\n" + main_body +
         "\n}\n";
}

// |actual - expected| within `tolerance`, relative above magnitude 1; NaN only matches NaN.
bool close_enough(double actual, double expected, double tolerance) {
  if (std::isnan(expected)) return std::isnan(actual);
  return std::fabs(actual - expected) <= tolerance * std::max(1.0, std::fabs(expected));
}

// Every pixel covered and equal to `expected` at its centre; the first few differences reported.
void expect_every_pixel(const twin::TwinImage& image, const PixelFunction& expected, double tolerance) {
  int failures = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!covered(image, x, y)) {
        if (++failures <= 5) ADD_FAILURE() << "pixel " << x << "," << y << " is not covered";
        continue;
      }
      const Pixel want = expected(x + 0.5, y + 0.5), got = rgba_at(image, x, y);
      for (size_t c = 0; c < 4; ++c)
        if (!close_enough(got[c], want[c], tolerance) && ++failures <= 5)
          ADD_FAILURE() << "pixel " << x << "," << y << " channel " << c << ": twin " << got[c] << ", expected "
                        << want[c];
    }
  EXPECT_EQ(failures, 0) << "pixels or channels that differ";
}

// One fragment body drawn on a full-screen quad and checked at every pixel.
struct FragmentCase {
  std::string body;
  PixelFunction expected;
};

// Each case as glslang gives it and optimised by spirv-opt (phis, merged blocks).
void check_fragment_cases(const std::string& declarations, const std::vector<FragmentCase>& cases, int width,
                          int height, const twin::BoundResources& resources, double tolerance) {
  for (const FragmentCase& c : cases)
    for (const Optimise optimise : {Optimise::no, Optimise::yes}) {
      SCOPED_TRACE(c.body + (optimise == Optimise::yes ? "\n(optimised)" : ""));
      auto program = glsl_program(pass_through_vertex, fragment_shader(declarations, c.body), optimise);
      ASSERT_TRUE(program) << program.error();
      auto image = draw_quad(*program, resources, width, height);
      ASSERT_TRUE(image) << image.error().to_string();
      expect_every_pixel(*image, c.expected, tolerance);
    }
}

// ---------------------------------------------------------------------------------------
// 1. Arithmetic and GLSL.std.450 built-ins

using Vec3 = std::array<double, 3>;

double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(const Vec3& v) {
  const double length = std::sqrt(dot3(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

TEST(TwinExecution, BuiltInsMatchCppAtEveryPixel) {
  constexpr int width = 13, height = 11;
  // Constants are dyadic, so the SPIR-V's float literals are the C++ doubles (and an
  // optimiser's x / 16 -> x * 0.0625 changes nothing).
  const std::string prelude = "float x = gl_FragCoord.x, y = gl_FragCoord.y;\n"
                              "float u = x / 16.0, v = y / 8.0;\n"
                              "vec3 I = normalize(vec3(u * 4.0 - 2.0, -0.5, v - 0.5));\n"
                              "vec3 N = normalize(vec3(0.25 + v * 0.5, 1.0, 0.125));\n";
  const auto uv = [](double x, double y) { return std::pair{x / 16.0, y / 8.0}; };
  const auto incident = [&](double x, double y) {
    const auto [u, v] = uv(x, y);
    return normalized({u * 4 - 2, -0.5, v - 0.5});
  };
  const auto normal_at = [&](double x, double y) {
    const auto [u, v] = uv(x, y);
    return normalized({0.25 + v * 0.5, 1.0, 0.125});
  };
  int total_internal_reflections = 0;
  const std::vector<FragmentCase> cases = {
      {prelude + "colour = vec4(pow(u + 0.5, v * 3.0 - 1.0), exp2(v * 4.0 - 2.0), log2(u + 0.25), "
                 "inversesqrt(u + 0.125));",
       [&](double x, double y) -> Pixel {
         const auto [u, v] = uv(x, y);
         return {std::pow(u + 0.5, v * 3 - 1), std::exp2(v * 4 - 2), std::log2(u + 0.25), 1 / std::sqrt(u + 0.125)};
       }},
      {prelude + "colour = vec4(normalize(vec3(x - 6.0, y - 5.0, 1.5)), length(vec2(x, y)));",
       [](double x, double y) -> Pixel {
         const Vec3 n = normalized({x - 6, y - 5, 1.5});
         return {n[0], n[1], n[2], std::hypot(x, y)};
       }},
      {prelude + "colour = vec4(reflect(I, N), dot(N, I));",
       [&](double x, double y) -> Pixel {
         const Vec3 i = incident(x, y), normal = normal_at(x, y);
         const double d = dot3(normal, i);
         return {i[0] - 2 * d * normal[0], i[1] - 2 * d * normal[1], i[2] - 2 * d * normal[2], d};
       }},
      {prelude + "colour = vec4(refract(I, N, 1.5), 0.0);",
       [&](double x, double y) -> Pixel {
         const Vec3 i = incident(x, y), normal = normal_at(x, y);
         const double eta = 1.5, d = dot3(normal, i), k = 1 - eta * eta * (1 - d * d);
         if (k < 0) {
           ++total_internal_reflections;
           return {0, 0, 0, 0};
         }
         const double s = eta * d + std::sqrt(k);
         return {eta * i[0] - s * normal[0], eta * i[1] - s * normal[1], eta * i[2] - s * normal[2], 0};
       }},
      {prelude + "colour = vec4(smoothstep(0.25, 0.75, u), mix(u, v, 0.3125), clamp(u * 3.0 - 1.0, 0.0, 1.0), "
                 "fract(x * 0.375));",
       [&](double x, double y) -> Pixel {
         const auto [u, v] = uv(x, y);
         const double t = std::clamp((u - 0.25) / 0.5, 0.0, 1.0);
         return {t * t * (3 - 2 * t), u * (1 - 0.3125) + v * 0.3125, std::clamp(u * 3 - 1, 0.0, 1.0),
                 x * 0.375 - std::floor(x * 0.375)};
       }},
      {prelude + "colour = vec4(mod(x - 7.0, 3.0), atan(y - 5.25, x - 6.25), mod(-x, 2.5), "
                 "atan(5.75 - y, 7.125 - x));",
       [](double x, double y) -> Pixel {
         const auto floored_mod = [](double a, double b) {   // GLSL: a - b * floor(a / b), sign of b
           const double r = std::fmod(a, b);
           return r != 0 && (r < 0) != (b < 0) ? r + b : r;
         };
         return {floored_mod(x - 7, 3), std::atan2(y - 5.25, x - 6.25), floored_mod(-x, 2.5),
                 std::atan2(5.75 - y, 7.125 - x)};
       }},
      // NaN from 0/0 at run time: min and max return the other operand (Mesa's fmin/fmax,
      // IEEE minNum/maxNum); clamp is min(max(x, lo), hi) as Mesa lowers it, so lo.
      {prelude + "float zero = x - x; float nan_value = zero / zero;\n"
                 "colour = vec4(max(nan_value, 0.0), min(nan_value, 1.0), max(0.25, nan_value), "
                 "clamp(nan_value, -1.0, 2.0));",
       [](double, double) -> Pixel { return {0, 1, 0.25, -1}; }},
  };
  check_fragment_cases("", cases, width, height, {}, 1e-12);
  // The refract case reaches both of its branches (counted over both variants).
  EXPECT_GT(total_internal_reflections, 0);
  EXPECT_LT(total_internal_reflections, 2 * width * height);
}

// ---------------------------------------------------------------------------------------
// 2. Structured control flow, divergent across pixels

// What the control-flow shader below computes, pixel by pixel, in C++.
void expect_control_flow(const twin::TwinImage& image) {
  const int width = image.width, height = image.height;
  const auto classify = [](int i) { return i < 3 ? 10 : i % 2 == 0 ? 20 : 30; };
  const auto first_multiple_of_7 = [](int start) {
    for (int i = start; i < start + start % 9; ++i)
      if (i % 7 == 0) return i;
    return -1;
  };
  int discarded = 0;
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      SCOPED_TRACE("pixel " + std::to_string(px) + "," + std::to_string(py));
      const Pixel got = rgba_at(image, px, py);
      if (px == 0 && py == 0) {
        EXPECT_TRUE(covered(image, px, py));
        EXPECT_EQ(got, (Pixel{-1, -1, -1, -1}));
        continue;
      }
      if ((px + 2 * py) % 5 == 4) {
        ++discarded;
        EXPECT_FALSE(covered(image, px, py)) << "a discarded pixel is written";
        EXPECT_EQ(got, (Pixel{0, 0, 0, 0}));
        continue;
      }
      ASSERT_TRUE(covered(image, px, py));
      const double side = px < py ? 1 : px == py ? 2 : 3;
      int acc = 0;
      for (int i = 0; i < 6; ++i) {
        if (i == py % 4) continue;
        for (int j = 0; j < 8; ++j) {
          if (j > px % 5) break;
          if (((i + j) & 1) == 1) continue;
          acc += i * j + 1;
        }
      }
      const int s = std::array{11, 10, 1100, 1000}[size_t(px % 4)];
      const int steps = (px + py + 2) / 3;
      const int d = std::max(2, (px + 1) / 2 * 2);
      const double a = (px + 0.5) * 0.75, whole = std::floor(a), sum = 0.25 + (a - whole);
      EXPECT_EQ(got[0], side + classify(px));
      EXPECT_EQ(got[1], acc + 1000.0 * first_multiple_of_7(px + py));
      EXPECT_EQ(got[2], s + 10000.0 * steps + 100000.0 * d);
      EXPECT_EQ(got[3], whole + 64 * sum);
    }
  EXPECT_GT(discarded, 0);
}

TEST(TwinExecution, DivergentControlFlowMatchesCpp) {
  // Big enough for several batches of lanes, on every thread.
  constexpr int width = 38, height = 26;
  const std::string fragment = R"(#version 450
layout(location = 0) out vec4 colour;

int classify(int i) {   // early returns
  if (i < 3) return 10;
  if (i % 2 == 0) return 20;
  return 30;
}

int first_multiple_of_7(int start) {   // a return from inside a loop
  for (int i = start; i < start + start % 9; ++i)
    if (i % 7 == 0) return i;
  return -1;
}

void split(float a, out float whole, inout float sum) {
  whole = floor(a);
  sum += a - whole;
}

void main() {
  int px = int(gl_FragCoord.x), py = int(gl_FragCoord.y);
  if (px == 0 && py == 0) {
    colour = vec4(-1.0);
    return;
  }
  float side;
  if (px < py) side = 1.0;
  else if (px == py) side = 2.0;
  else side = 3.0;

  int acc = 0;
  for (int i = 0; i < 6; ++i) {
    if (i == py % 4) continue;
    for (int j = 0; j < 8; ++j) {
      if (j > px % 5) break;
      if (((i + j) & 1) == 1) continue;
      acc += i * j + 1;
    }
  }

  int s = 0;
  switch (px % 4) {
    case 0: s += 1;
    case 1: s += 10; break;
    case 2: s += 100;
    default: s += 1000;
  }

  int steps = 0;
  for (int k = px + py; k > 0; k -= 3) ++steps;
  int d = 0;
  do { d += 2; } while (d < px);

  float whole, sum = 0.25;
  split(gl_FragCoord.x * 0.75, whole, sum);
  if ((px + 2 * py) % 5 == 4) discard;
  colour = vec4(side + float(classify(px)), float(acc) + 1000.0 * float(first_multiple_of_7(px + py)),
                float(s + 10000 * steps + 100000 * d), whole + 64.0 * sum);
}
)";
  for (const Optimise optimise : {Optimise::no, Optimise::yes}) {
    SCOPED_TRACE(optimise == Optimise::yes ? "optimised" : "as glslang gives it");
    auto program = glsl_program(pass_through_vertex, fragment, optimise);
    ASSERT_TRUE(program) << program.error();
    auto image = draw_quad(*program, {}, width, height);
    ASSERT_TRUE(image) << image.error().to_string();
    expect_control_flow(*image);
  }
}

// A switch inside a loop (continue from a case, break out of the switch from inside an
// if), a loop left by a pixel-dependent break, short-circuit && and || (phis) and ?:.
TEST(TwinExecution, SwitchInLoopAndShortCircuitMatchCpp) {
  constexpr int width = 12, height = 10;
  const std::string body = R"(
int px = int(gl_FragCoord.x), py = int(gl_FragCoord.y);
int total = 0;
for (int i = 0; i < 8; ++i) {
  switch ((i + px) % 3) {
    case 0: continue;
    case 1: total += i; break;
    default:
      if (i > py) break;
      total += 100;
  }
  total += 1000;
  if (total > 3000 + 200 * py) break;
}
bool both = px > 3 && py < 5;
bool either = px == 1 || (py > 2 && px % 2 == 0);
float choice = px > py ? gl_FragCoord.x : -gl_FragCoord.y;
colour = vec4(float(total), both ? 1.0 : 0.0, either ? 2.0 : -2.0, choice);
)";
  check_fragment_cases("", {{body, [](double x, double y) -> Pixel {
                               const int px = int(x), py = int(y);
                               int total = 0;
                               for (int i = 0; i < 8; ++i) {
                                 const int which = (i + px) % 3;
                                 if (which == 0) continue;
                                 if (which == 1) total += i;
                                 else if (i <= py) total += 100;
                                 total += 1000;
                                 if (total > 3000 + 200 * py) break;
                               }
                               const bool both = px > 3 && py < 5;
                               const bool either = px == 1 || (py > 2 && px % 2 == 0);
                               return {double(total), both ? 1.0 : 0.0, either ? 2.0 : -2.0, px > py ? x : -y};
                             }}},
                       width, height, {}, 0);
}

// Whether a block of `m` has a phi that takes another phi of the same block.
bool has_phi_reading_a_sibling_phi(const twin::Module& m) {
  for (const auto& [id, function] : m.functions)
    for (const twin::Block& block : function.blocks) {
      std::vector<uint32_t> phis;
      for (uint32_t i = block.first; i < block.last && spv::Op(m.instructions[i].op) == spv::Op::OpPhi; ++i)
        phis.push_back(m.instructions[i].result);
      for (uint32_t i = block.first; i < block.first + phis.size(); ++i) {
        const auto ops = m.operands_of(m.instructions[i]);
        for (size_t k = 0; k < ops.size(); k += 2)
          if (std::find(phis.begin(), phis.end(), ops[k]) != phis.end()) return true;
      }
    }
  return false;
}

// Optimised SPIR-V (as the compile stage gives HLSL) keeps loop variables in phis; a swap
// makes one header phi take another from the back edge: phis are parallel copies.
TEST(TwinExecution, LoopHeaderPhisAreParallelCopies) {
  const std::string fragment = fragment_shader("", R"(
int n = int(gl_FragCoord.x);
float a = 0.0, b = 1.0;
for (int i = 0; i < n; ++i) {
  float next = a + b;
  a = b;
  b = next;
}
colour = vec4(a, b, float(n), 1.0);
)");
  auto vertex_spirv = glsl_spirv(shaderbed::Stage::vertex, pass_through_vertex);
  auto fragment_spirv = glsl_spirv(shaderbed::Stage::fragment, fragment);
  ASSERT_TRUE(vertex_spirv && fragment_spirv);
  auto optimised_spirv = optimised(*fragment_spirv);
  ASSERT_TRUE(optimised_spirv) << optimised_spirv.error();
  auto program = twin::load_program(*vertex_spirv, "main", *optimised_spirv, "main");
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_TRUE(has_phi_reading_a_sibling_phi(*program->fragment)) << "the optimiser no longer makes the swap phis";
  auto image = draw_quad(*program, {}, 14, 2);
  ASSERT_TRUE(image) << image.error().to_string();
  expect_every_pixel(
      *image,
      [](double x, double) -> Pixel {
        double a = 0, b = 1;
        for (int i = 0; i < int(x); ++i) {
          const double next = a + b;
          a = b;
          b = next;
        }
        return {a, b, std::trunc(x), 1};
      },
      0);
}

// ---------------------------------------------------------------------------------------
// 3. Matrices and std140 uniform blocks

using Matrix = std::vector<std::vector<double>>;   // [row][column]

Matrix minor_of(const Matrix& m, size_t row, size_t column) {
  Matrix out;
  for (size_t r = 0; r < m.size(); ++r) {
    if (r == row) continue;
    out.emplace_back();
    for (size_t c = 0; c < m.size(); ++c)
      if (c != column) out.back().push_back(m[r][c]);
  }
  return out;
}

// Laplace expansion along the first row (independent of the twin's elimination).
double laplace_determinant(const Matrix& m) {
  if (m.size() == 1) return m[0][0];
  double sum = 0;
  for (size_t c = 0; c < m.size(); ++c) sum += (c % 2 ? -1 : 1) * m[0][c] * laplace_determinant(minor_of(m, 0, c));
  return sum;
}

// Adjugate over determinant.
Matrix adjugate_inverse(const Matrix& m) {
  const double det = laplace_determinant(m);
  Matrix inverse(m.size(), std::vector<double>(m.size()));
  for (size_t r = 0; r < m.size(); ++r)
    for (size_t c = 0; c < m.size(); ++c)
      inverse[c][r] = ((r + c) % 2 ? -1 : 1) * laplace_determinant(minor_of(m, r, c)) / det;
  return inverse;
}

std::vector<double> times(const Matrix& m, const std::vector<double>& v) {
  std::vector<double> out(m.size(), 0.0);
  for (size_t r = 0; r < m.size(); ++r)
    for (size_t c = 0; c < v.size(); ++c) out[r] += m[r][c] * v[c];
  return out;
}

Matrix transposed(const Matrix& m) {
  Matrix t(m[0].size(), std::vector<double>(m.size()));
  for (size_t r = 0; r < m.size(); ++r)
    for (size_t c = 0; c < m[0].size(); ++c) t[c][r] = m[r][c];
  return t;
}

Matrix product(const Matrix& a, const Matrix& b) {
  Matrix out(a.size(), std::vector<double>(b[0].size(), 0.0));
  for (size_t r = 0; r < a.size(); ++r)
    for (size_t c = 0; c < b[0].size(); ++c)
      for (size_t k = 0; k < b.size(); ++k) out[r][c] += a[r][k] * b[k][c];
  return out;
}

Pixel pixel_of(const std::vector<double>& v, double last = 0) {
  return {v[0], v[1], v[2], v.size() > 3 ? v[3] : last};
}

TEST(TwinExecution, Std140MatricesArraysAndStructs) {
  constexpr int width = 9, height = 7;
  const std::string declarations = R"(
struct Light { vec3 direction; float intensity; };
layout(std140, set = 0, binding = 0) uniform Transforms {
  mat4 m;                      // offset 0
  layout(row_major) mat4 r;    // offset 64
  mat3 n;                      // offset 128: three vec3 columns, 16 bytes apart
  vec4 colours[3];             // offset 176
  float weights[4];            // offset 224, stride 16
  Light light;                 // offset 288: direction, intensity at 300
  mat2x3 wide;                 // offset 304: two vec3 columns, 16 bytes apart
  layout(row_major) mat2x3 wide_rows;   // offset 336: three rows of two, 16 bytes apart
  mat2 pair[2];                // offset 384: array stride 32
} u;
)";
  const Matrix M = {{2, 0, 1, 0.5}, {1, 3, 0, 0}, {0, 1, 4, 0.25}, {0.5, 0, 0, 1}};
  const Matrix R = {{1, 2, 0, 0}, {0, 1, 3, 0}, {0, 0, 1, 4}, {5, 0, 0, 1}};
  const Matrix N = {{2, 1, 0}, {0, 1, 0.5}, {1, 0, 3}};
  const std::array<Pixel, 3> colours = {{{1, 10, 0, 1}, {2, 20, 0.5, 1}, {3, 30, 1, 1}}};
  const std::array<double, 4> weights = {0.25, 0.5, 0.75, 1};
  const Vec3 direction = {0.5, -1, 2};
  const double intensity = 1.5;
  const Matrix W = {{1, 2}, {3, -1}, {0.5, 4}};    // 3 rows, 2 columns
  const Matrix Q = {{2, 0.5}, {-1, 3}, {1, 1}};
  const std::array<Matrix, 2> P = {Matrix{{1, 2}, {3, 4}}, Matrix{{-1, 0.5}, {0.25, 2}}};
  constexpr size_t block_size = 448;

  // std140 by hand; the padding holds -999 so that reading it shows.
  BlockBytes block(block_size);
  for (size_t at = 0; at < block_size; at += 4) block.put_float(at, -999);
  for (size_t c = 0; c < 4; ++c)
    for (size_t r = 0; r < 4; ++r) {
      block.put_float(c * 16 + r * 4, float(M[r][c]));        // column-major: a column per 16 bytes
      block.put_float(64 + r * 16 + c * 4, float(R[r][c]));   // row-major: a row per 16 bytes
    }
  for (size_t c = 0; c < 3; ++c)
    for (size_t r = 0; r < 3; ++r) block.put_float(128 + c * 16 + r * 4, float(N[r][c]));
  for (size_t i = 0; i < 3; ++i)
    for (size_t k = 0; k < 4; ++k) block.put_float(176 + i * 16 + k * 4, float(colours[i][k]));
  for (size_t i = 0; i < 4; ++i) block.put_float(224 + i * 16, float(weights[i]));
  for (size_t k = 0; k < 3; ++k) block.put_float(288 + k * 4, float(direction[k]));
  block.put_float(300, float(intensity));
  for (size_t c = 0; c < 2; ++c)
    for (size_t r = 0; r < 3; ++r) {
      block.put_float(304 + c * 16 + r * 4, float(W[r][c]));
      block.put_float(336 + r * 16 + c * 4, float(Q[r][c]));
    }
  for (size_t k = 0; k < 2; ++k)
    for (size_t c = 0; c < 2; ++c)
      for (size_t r = 0; r < 2; ++r) block.put_float(384 + k * 32 + c * 16 + r * 4, float(P[k][r][c]));
  twin::BoundResources resources;
  resources.buffers[{0, 0}] = {block.bytes(), {}};

  const std::string v = "vec4 v = vec4(gl_FragCoord.x, gl_FragCoord.y, 1.0, 2.0);\n";
  const auto vec = [](double x, double y) { return std::vector<double>{x, y, 1, 2}; };
  const std::vector<FragmentCase> cases = {
      {v + "colour = u.m * v;", [&](double x, double y) { return pixel_of(times(M, vec(x, y))); }},
      {v + "colour = v * u.m;", [&](double x, double y) { return pixel_of(times(transposed(M), vec(x, y))); }},
      {v + "colour = u.r * v;", [&](double x, double y) { return pixel_of(times(R, vec(x, y))); }},
      {v + "colour = (u.m * u.r) * v;", [&](double x, double y) { return pixel_of(times(product(M, R), vec(x, y))); }},
      {v + "colour = transpose(u.r) * v;",
       [&](double x, double y) { return pixel_of(times(transposed(R), vec(x, y))); }},
      {v + "colour = inverse(u.m) * v;",
       [&](double x, double y) { return pixel_of(times(adjugate_inverse(M), vec(x, y))); }},
      {"colour = vec4(u.n * vec3(gl_FragCoord.xy, 1.0), determinant(u.n));",
       [&](double x, double y) { return pixel_of(times(N, {x, y, 1}), laplace_determinant(N)); }},
      {"colour = vec4(inverse(u.n) * vec3(gl_FragCoord.xy, 1.0), 0.0);",
       [&](double x, double y) { return pixel_of(times(adjugate_inverse(N), {x, y, 1})); }},
      {"colour = vec4(determinant(u.m), determinant(u.r), determinant(u.n), 0.0);",
       [&](double, double) -> Pixel {
         return {laplace_determinant(M), laplace_determinant(R), laplace_determinant(N), 0};
       }},
      // Columns and elements of each layout.
      {"colour = u.r[1] + 10.0 * u.m[2];",
       [&](double, double) -> Pixel {
         return {R[0][1] + 10 * M[0][2], R[1][1] + 10 * M[1][2], R[2][1] + 10 * M[2][2], R[3][1] + 10 * M[3][2]};
       }},
      {"mat3 n = u.n; colour = vec4(n[1], u.r[2][3] + 10.0 * u.m[2][3]);",
       [&](double, double) -> Pixel { return {N[0][1], N[1][1], N[2][1], R[3][2] + 10 * M[3][2]}; }},
      // Arrays indexed per pixel, and a struct member.
      {"colour = u.colours[int(gl_FragCoord.x) % 3] * u.weights[int(gl_FragCoord.y) % 4];",
       [&](double x, double y) -> Pixel {
         const Pixel c = colours[size_t(int(x) % 3)];
         const double w = weights[size_t(int(y) % 4)];
         return {c[0] * w, c[1] * w, c[2] * w, c[3] * w};
       }},
      {"colour = vec4(u.light.direction * u.light.intensity, u.weights[3]);",
       [&](double, double) -> Pixel {
         return {direction[0] * intensity, direction[1] * intensity, direction[2] * intensity, weights[3]};
       }},
      // Non-square matrices in both layouts, and an array of matrices indexed per pixel.
      {"colour = vec4(u.wide * gl_FragCoord.xy, 0.0);",
       [&](double x, double y) { return pixel_of(times(W, {x, y})); }},
      {"colour = vec4(vec3(gl_FragCoord.xy, 1.0) * u.wide, 0.0, 0.0);",
       [&](double x, double y) -> Pixel {
         const auto r = times(transposed(W), {x, y, 1});
         return {r[0], r[1], 0, 0};
       }},
      {"colour = vec4(u.wide_rows * gl_FragCoord.xy, 0.0);",
       [&](double x, double y) { return pixel_of(times(Q, {x, y})); }},
      {"colour = vec4(u.pair[int(gl_FragCoord.x) % 2] * gl_FragCoord.xy, u.pair[1][1]);",
       [&](double x, double y) -> Pixel {
         const auto r = times(P[size_t(int(x) % 2)], {x, y});
         return {r[0], r[1], P[1][0][1], P[1][1][1]};
       }},
      // Component-wise matrix operations and conversions.
      {"colour = vec4(matrixCompMult(u.n, mat3(u.m))[2], 0.0);",
       [&](double, double) -> Pixel { return {N[0][2] * M[0][2], N[1][2] * M[1][2], N[2][2] * M[2][2], 0}; }},
      {"colour = vec4(outerProduct(vec3(gl_FragCoord.xy, 1.0), vec2(0.5, 3.0))[1], 0.0);",
       [](double x, double y) -> Pixel { return {x * 3, y * 3, 3, 0}; }},
      {"colour = (-u.m + 2.0 * u.r - u.m / 4.0)[3];",
       [&](double, double) -> Pixel {
         Pixel p{};
         for (size_t r = 0; r < 4; ++r) p[r] = -M[r][3] + 2 * R[r][3] - M[r][3] / 4;
         return p;
       }},
      // A local matrix written through a column index that differs per pixel.
      {v + "mat4 local = u.m; local[int(gl_FragCoord.y) % 4][1] = gl_FragCoord.x; colour = local * v;",
       [&](double x, double y) {
         Matrix local = M;
         local[1][size_t(int(y) % 4)] = x;
         return pixel_of(times(local, vec(x, y)));
       }},
  };
  check_fragment_cases(declarations, cases, width, height, resources, 1e-12);
}

// ---------------------------------------------------------------------------------------
// 4. Integers and bits

TEST(TwinExecution, IntegerArithmeticBitsAndConversions) {
  constexpr int width = 16, height = 12;
  // a in [-7, 8]; b odd, so never 0, and negative in the upper rows.
  const std::string prelude = "int px = int(gl_FragCoord.x), py = int(gl_FragCoord.y);\n"
                              "int a = px - 7, b = (py - 5) | 1;\n"
                              "uint ua = uint(px * 37 + 5) * 2654435761u, ub = uint(py + 1);\n";
  struct Values {
    int32_t px, py, a, b;
    uint32_t ua, ub;
  };
  const auto values = [](double x, double y) {
    const int32_t px = int32_t(x), py = int32_t(y);
    return Values{px, py, px - 7, (py - 5) | 1, uint32_t(px * 37 + 5) * 2654435761u, uint32_t(py + 1)};
  };
  // GLSL's int % compiles to OpSMod: the remainder takes the divisor's sign.
  const auto smod = [](int32_t x, int32_t y) {
    const int32_t r = x % y;
    return r != 0 && (r < 0) != (y < 0) ? r + y : r;
  };
  const auto wrap = [](int64_t x) { return double(int32_t(uint32_t(uint64_t(x)))); };
  const std::vector<FragmentCase> cases = {
      {prelude + "colour = vec4(a / b, a % b, float(ua / ub), float(ua % ub));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {double(v.a / v.b), double(smod(v.a, v.b)), double(v.ua / v.ub), double(v.ua % v.ub)};
       }},
      {prelude + "colour = vec4(a << 3, a >> 1, float(uint(a) >> 28), float((ua << 30) >> 30));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {wrap(int64_t(uint32_t(v.a) << 3)), double(v.a >> 1), double(uint32_t(v.a) >> 28),
                 double(uint32_t(v.ua << 30) >> 30)};
       }},
      {prelude + "colour = vec4(1 << py, float(ua >> uint(px)), -(a >> (py % 4)), float(uint(b) >> 1));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {double(1 << v.py), double(v.ua >> v.px), double(-(v.a >> (v.py % 4))), double(uint32_t(v.b) >> 1)};
       }},
      {prelude + "colour = vec4(a & 0x5a, a | 0x101, a ^ b, ~a);",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {double(v.a & 0x5a), double(v.a | 0x101), double(v.a ^ v.b), double(~v.a)};
       }},
      {prelude + "colour = vec4(float(~ua & 0xFFFFu), float(ua ^ 0xDEADBEEFu), float(ua & ~ub), float(ua | ub));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {double(~v.ua & 0xFFFFu), double(v.ua ^ 0xDEADBEEFu), double(v.ua & ~v.ub), double(v.ua | v.ub)};
       }},
      // Float to integer in range only (out of range is the device's choice): truncation.
      {"float f = (gl_FragCoord.x - 8.0) * 0.75 + gl_FragCoord.y * 0.0625;\n"
       "colour = vec4(int(f), uint(abs(f) * 1000.0), float(int(-f) * 3), float(3000000000u + uint(gl_FragCoord.x)));",
       [](double x, double y) -> Pixel {
         const double f = (x - 8) * 0.75 + y * 0.0625;
         return {std::trunc(f), std::trunc(std::fabs(f) * 1000), std::trunc(-f) * 3, 3000000000.0 + std::trunc(x)};
       }},
      {"uint bits = floatBitsToUint(gl_FragCoord.x);\n"
       "colour = vec4(float(bits >> 16), float(bits & 0xFFFFu), "
       "uintBitsToFloat(0x3F800000u + uint(gl_FragCoord.x) * 0x8000u), intBitsToFloat(floatBitsToInt(-gl_FragCoord.y)));",
       [](double x, double y) -> Pixel {
         const uint32_t bits = std::bit_cast<uint32_t>(float(x));
         return {double(bits >> 16), double(bits & 0xFFFFu),
                 double(std::bit_cast<float>(uint32_t(0x3F800000u + uint32_t(x) * 0x8000u))), -y};
       }},
      // Two's complement wrapping of signed addition and multiplication.
      {prelude + "colour = vec4(0x7FFFFFFF + px, (a * 65537) * 65537, -a, abs(a));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {wrap(int64_t(0x7FFFFFFF) + v.px), wrap(int64_t(uint32_t(uint32_t(v.a) * 65537u) * 65537u)),
                 double(-v.a), double(std::abs(v.a))};
       }},
      {prelude + "colour = vec4(ua > 0x80000000u, a < b, min(a, b) + 100 * max(a, b), float(max(ua, ub) == ua));",
       [&](double x, double y) -> Pixel {
         const Values v = values(x, y);
         return {double(v.ua > 0x80000000u), double(v.a < v.b), double(std::min(v.a, v.b) + 100 * std::max(v.a, v.b)),
                 double(std::max(v.ua, v.ub) == v.ua)};
       }},
  };
  check_fragment_cases("", cases, width, height, {}, 0);
}

// ---------------------------------------------------------------------------------------
// 5. Derivatives within 2x2 quads

TEST(TwinExecution, DerivativesAreQuadDifferences) {
  // Odd sizes: the last column and row of quads reach outside the image (helper lanes).
  constexpr int width = 13, height = 9;
  const std::string prelude = "float x = gl_FragCoord.x, y = gl_FragCoord.y;\n";
  // Centre of the quad's first column and row.
  const auto quad_x = [](double x) { return double(int(x) & ~1) + 0.5; };
  const auto quad_y = [](double y) { return double(int(y) & ~1) + 0.5; };
  const std::vector<FragmentCase> cases = {
      // d(x^2)/dx across a quad's row: (x0 + 1)^2 - x0^2 = 2 x0 + 1.
      {prelude + "colour = vec4(dFdx(x), dFdy(y), dFdx(x * x), dFdy(y * y));",
       [&](double x, double y) -> Pixel { return {1, 1, 2 * quad_x(x) + 1, 2 * quad_y(y) + 1}; }},
      // Fine: d(xy)/dx in the pixel's own row is its y; coarse: the quad's first row's.
      {prelude + "colour = vec4(dFdxFine(x * y), dFdyFine(x * y), dFdxCoarse(x * y), dFdyCoarse(x * y));",
       [&](double x, double y) -> Pixel { return {y, x, quad_y(y), quad_x(x)}; }},
      {prelude + "colour = vec4(fwidth(x * y), fwidthFine(x * x), fwidthCoarse(x * y), dFdx(y));",
       [&](double x, double y) -> Pixel { return {x + y, 2 * quad_x(x) + 1, quad_x(x) + quad_y(y), 0}; }},
  };
  check_fragment_cases("", cases, width, height, {}, 1e-12);
}

TEST(TwinExecution, DerivativesAtTriangleEdgesUseHelperLanes) {
  constexpr int width = 16, height = 16;
  // A triangle whose edges cut through quads; value is linear in window x (w = 1).
  const std::string vertex = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 0) out float value;
void main() { gl_Position = position; value = position.x * 3.0 + position.y; }
)";
  const std::string fragment = R"(#version 450
layout(location = 0) in float value;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(dFdx(gl_FragCoord.x), dFdy(gl_FragCoord.y), dFdx(value), dFdy(value)); }
)";
  auto program = glsl_program(vertex, fragment);
  ASSERT_TRUE(program) << program.error();
  const Mesh triangle{.streams = {{.location = 0, .values = {-0.9, -0.8, 0.5, 1, 0.7, -0.3, 0.5, 1, -0.2, 0.9, 0.5, 1}}},
                      .vertex_count = 3,
                      .indices = {0, 1, 2}};
  auto image = draw_mesh(*program, triangle, {}, width, height);
  ASSERT_TRUE(image) << image.error().to_string();
  // x_ndc = 2 x / W - 1 and y_ndc = 1 - 2 y / H, so value changes by 6 / W per pixel in x
  // and by -2 / H in y.
  int pixels = 0, partial_quads = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!covered(*image, x, y)) continue;
      ++pixels;
      const int qx = x & ~1, qy = y & ~1;
      if (!(covered(*image, qx, qy) && covered(*image, qx + 1, qy) && covered(*image, qx, qy + 1) &&
            covered(*image, qx + 1, qy + 1)))
        ++partial_quads;
      const Pixel got = rgba_at(*image, x, y), want = {1, 1, 6.0 / width, -2.0 / height};
      for (size_t c = 0; c < 4; ++c)
        EXPECT_TRUE(close_enough(got[c], want[c], 1e-12))
            << "pixel " << x << "," << y << " channel " << c << ": " << got[c] << " vs " << want[c];
    }
  EXPECT_GT(pixels, 40);
  EXPECT_GT(partial_quads, 0) << "the triangle's edges should cut quads";
}

// ---------------------------------------------------------------------------------------
// 6. Varyings: perspective-correct, noperspective, flat

// One triangle with its own w at each vertex (clip = ndc * w) in a 16x16 image, and a
// value per vertex; NDC positions in eighths land on whole pixels, so the rasteriser's
// snapping changes nothing and the barycentrics below are exact.
struct PerspectiveTriangle {
  static constexpr int size = 16;
  std::array<std::array<double, 2>, 3> ndc = {{{-0.75, -0.75}, {0.875, -0.5}, {-0.25, 0.875}}};
  std::array<double, 3> w = {1, 2, 4}, depth = {0.25, 0.5, 0.75}, value = {1, 5, 9};

  // Positions at location 0, (value, 0, 0, 1) at location 1, listed from vertex `first`.
  Mesh mesh(uint32_t first) const {
    Mesh out{.vertex_count = 3, .indices = {first, (first + 1) % 3, (first + 2) % 3}};
    twin::VertexStream position{.location = 0}, values{.location = 1};
    for (size_t i = 0; i < 3; ++i) {
      position.values.insert(position.values.end(), {ndc[i][0] * w[i], ndc[i][1] * w[i], depth[i] * w[i], w[i]});
      values.values.insert(values.values.end(), {value[i], 0, 0, 1});
    }
    out.streams = {position, values};
    return out;
  }

  // Screen-space barycentrics of window point (x, y): positive inside.
  std::array<double, 3> screen_weights(double x, double y) const {
    std::array<std::array<double, 2>, 3> p;
    for (size_t i = 0; i < 3; ++i) p[i] = {(ndc[i][0] + 1) / 2 * size, (1 - ndc[i][1]) / 2 * size};
    const auto edge = [](const std::array<double, 2>& a, const std::array<double, 2>& b, double qx, double qy) {
      return (b[0] - a[0]) * (qy - a[1]) - (b[1] - a[1]) * (qx - a[0]);
    };
    const double area = edge(p[0], p[1], p[2][0], p[2][1]);
    return {edge(p[1], p[2], x, y) / area, edge(p[2], p[0], x, y) / area, edge(p[0], p[1], x, y) / area};
  }

  // f(vertex value) at the vertices, interpolated as smooth (perspective-correct) and noperspective.
  static double smooth(const std::array<double, 3>& s, const std::array<double, 3>& w, const std::array<double, 3>& f) {
    double over_w = 0, sum = 0;
    for (size_t i = 0; i < 3; ++i) {
      over_w += s[i] / w[i];
      sum += s[i] / w[i] * f[i];
    }
    return sum / over_w;
  }
  static double linear(const std::array<double, 3>& s, const std::array<double, 3>& f) {
    return s[0] * f[0] + s[1] * f[1] + s[2] * f[2];
  }
  std::array<double, 3> of_value(double (*f)(double)) const { return {f(value[0]), f(value[1]), f(value[2])}; }
};

// Calls check(px, py, s) for every pixel strictly inside the triangle, after checking
// that exactly those (and no pixel strictly outside) are covered in `image`.
template <class Check>
void for_each_inside(const PerspectiveTriangle& triangle, const twin::TwinImage& image, Check check) {
  int inside = 0;
  for (int py = 0; py < triangle.size; ++py)
    for (int px = 0; px < triangle.size; ++px) {
      const auto s = triangle.screen_weights(px + 0.5, py + 0.5);
      const double nearest_edge = std::min({s[0], s[1], s[2]});
      if (std::fabs(nearest_edge) < 1e-9) continue;   // on an edge: the fill rule's choice
      SCOPED_TRACE("pixel " + std::to_string(px) + "," + std::to_string(py));
      ASSERT_EQ(covered(image, px, py), nearest_edge > 0);
      if (nearest_edge < 0) continue;
      ++inside;
      check(px, py, s);
    }
  EXPECT_GT(inside, 30);
}

TEST(TwinExecution, SmoothNoperspectiveAndFlatVaryings) {
  const std::string vertex = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 vertex_value;
layout(location = 0) out float smooth_value;
layout(location = 1) noperspective out float linear_value;
layout(location = 2) flat out float flat_value;
layout(location = 3) flat out int flat_index;
void main() {
  gl_Position = position;
  smooth_value = vertex_value.x;
  linear_value = vertex_value.x;
  flat_value = vertex_value.x;
  flat_index = gl_VertexIndex;
}
)";
  const std::string declarations = R"(
layout(location = 0) in float smooth_value;
layout(location = 1) noperspective in float linear_value;
layout(location = 2) flat in float flat_value;
layout(location = 3) flat in int flat_index;
)";
  auto values = glsl_program(vertex, fragment_shader(declarations, "colour = vec4(smooth_value, linear_value, "
                                                                   "flat_value, gl_FragCoord.w);"));
  ASSERT_TRUE(values) << values.error();
  auto coordinates = glsl_program(vertex, fragment_shader(declarations, "colour = vec4(gl_FragCoord.z, "
                                                                        "float(flat_index), gl_FragCoord.xy);"));
  ASSERT_TRUE(coordinates) << coordinates.error();

  const PerspectiveTriangle triangle;
  const int size = triangle.size;
  // The same triangle listed from vertex 0 and from vertex 1: flat takes the first listed.
  for (const uint32_t first : {0u, 1u}) {
    SCOPED_TRACE("triangle listed from vertex " + std::to_string(first));
    const Mesh mesh = triangle.mesh(first);
    auto value_image = draw_mesh(*values, mesh, {}, size, size);
    ASSERT_TRUE(value_image) << value_image.error().to_string();
    auto coordinate_image = draw_mesh(*coordinates, mesh, {}, size, size);
    ASSERT_TRUE(coordinate_image) << coordinate_image.error().to_string();
    int perspective_differs = 0;
    for_each_inside(triangle, *value_image, [&](int px, int py, const std::array<double, 3>& s) {
      const double smooth = PerspectiveTriangle::smooth(s, triangle.w, triangle.value);
      const double linear = PerspectiveTriangle::linear(s, triangle.value);
      // gl_FragCoord: z = z_ndc, linear in the window; w = 1 / w_clip, whose reciprocal is.
      const double z = PerspectiveTriangle::linear(s, triangle.depth);
      const double one_over_w = s[0] / triangle.w[0] + s[1] / triangle.w[1] + s[2] / triangle.w[2];
      if (std::fabs(smooth - linear) > 1e-3) ++perspective_differs;
      const Pixel got = rgba_at(*value_image, px, py), at = rgba_at(*coordinate_image, px, py);
      EXPECT_NEAR(got[0], smooth, 1e-12);
      EXPECT_NEAR(got[1], linear, 1e-12);
      EXPECT_EQ(got[2], triangle.value[first]);
      EXPECT_NEAR(got[3], one_over_w, 1e-12);
      EXPECT_NEAR(at[0], z, 1e-12);
      EXPECT_EQ(at[1], double(first));
      EXPECT_EQ(at[2], px + 0.5);
      EXPECT_EQ(at[3], py + 0.5);
    });
    EXPECT_GT(perspective_differs, 10) << "the test needs w to matter";
  }
}

// Varyings in an interface block (interpolation on its members), arrays, a matrix, and
// two variables sharing one location by component.
TEST(TwinExecution, BlockArrayMatrixAndComponentVaryings) {
  const std::string vertex = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 vertex_value;
layout(location = 0) out Block { flat int id; noperspective float linear_value; vec2 pair[2]; } data;
layout(location = 4) out mat2 m;
layout(location = 6, component = 0) out vec2 ab;
layout(location = 6, component = 2) out float c;
void main() {
  gl_Position = position;
  float a = vertex_value.x;
  data.id = 10 + gl_VertexIndex;
  data.linear_value = a;
  data.pair[0] = vec2(a * 2.0, -1.0);
  data.pair[1] = vec2(0.5, a * 3.0);
  m = mat2(a, a + 1.0, a * 4.0, 0.25);
  ab = vec2(a + 100.0, a * 5.0);
  c = -a;
}
)";
  const std::string declarations = R"(
layout(location = 0) in Block { flat int id; noperspective float linear_value; vec2 pair[2]; } data;
layout(location = 4) in mat2 m;
layout(location = 6, component = 0) in vec2 ab;
layout(location = 6, component = 2) in float c;
)";
  auto first = glsl_program(vertex, fragment_shader(declarations, "colour = vec4(float(data.id), data.linear_value, "
                                                                  "data.pair[1].y, m[1][0]);"));
  ASSERT_TRUE(first) << first.error();
  auto second = glsl_program(vertex, fragment_shader(declarations, "colour = vec4(data.pair[0].x, m[0].y, ab.y, c);"));
  ASSERT_TRUE(second) << second.error();
  const PerspectiveTriangle triangle;
  const Mesh mesh = triangle.mesh(0);
  auto first_image = draw_mesh(*first, mesh, {}, triangle.size, triangle.size);
  ASSERT_TRUE(first_image) << first_image.error().to_string();
  auto second_image = draw_mesh(*second, mesh, {}, triangle.size, triangle.size);
  ASSERT_TRUE(second_image) << second_image.error().to_string();
  const auto smooth = [&](const std::array<double, 3>& s, double (*f)(double)) {
    return PerspectiveTriangle::smooth(s, triangle.w, triangle.of_value(f));
  };
  for_each_inside(triangle, *first_image, [&](int px, int py, const std::array<double, 3>& s) {
    const Pixel got = rgba_at(*first_image, px, py);
    EXPECT_EQ(got[0], 10.0) << "a flat block member takes the first vertex's value";
    EXPECT_NEAR(got[1], PerspectiveTriangle::linear(s, triangle.value), 1e-12);
    EXPECT_NEAR(got[2], smooth(s, [](double a) { return a * 3; }), 1e-12);
    EXPECT_NEAR(got[3], smooth(s, [](double a) { return a * 4; }), 1e-12);
    const Pixel more = rgba_at(*second_image, px, py);
    EXPECT_NEAR(more[0], smooth(s, [](double a) { return a * 2; }), 1e-12);
    EXPECT_NEAR(more[1], smooth(s, [](double a) { return a + 1; }), 1e-12);
    EXPECT_NEAR(more[2], smooth(s, [](double a) { return a * 5; }), 1e-12);
    EXPECT_NEAR(more[3], smooth(s, [](double a) { return -a; }), 1e-12);
  });
}

// ---------------------------------------------------------------------------------------
// 7. gl_FrontFacing and culling

TEST(TwinExecution, FrontFacingIsClockwiseOnScreen) {
  constexpr int width = 16, height = 16;
  auto program = glsl_program(pass_through_vertex,
                              fragment_shader("", "colour = gl_FrontFacing ? vec4(1, 0, 0, 1) : vec4(0, 1, 0, 1);"));
  ASSERT_TRUE(program) << program.error();
  // Window (2, 2), (14, 2), (2, 14): top-left, top-right, bottom-left, clockwise on a
  // screen whose y goes down. w = 2 for the second copy: facing does not depend on it.
  Mesh mesh{.streams = {{.location = 0,
                         .values = {-0.75, 0.75, 0.5, 1, 0.75, 0.75, 0.5, 1, -0.75, -0.75, 0.5, 1,
                                    -1.5, 1.5, 1, 2, 1.5, 1.5, 1, 2, -1.5, -1.5, 1, 2}}},
            .vertex_count = 6};
  struct Order {
    std::vector<uint32_t> indices;
    bool front;
  };
  for (const Order& order : {Order{{0, 1, 2}, true}, Order{{0, 2, 1}, false}, Order{{3, 4, 5}, true},
                             Order{{4, 3, 5}, false}}) {
    SCOPED_TRACE("indices " + std::to_string(order.indices[0]) + std::to_string(order.indices[1]) +
                 std::to_string(order.indices[2]));
    mesh.indices = order.indices;
    for (const twin::Cull cull : {twin::Cull::none, twin::Cull::back, twin::Cull::front}) {
      auto image = draw_mesh(*program, mesh, {}, width, height, {.cull = cull});
      ASSERT_TRUE(image) << image.error().to_string();
      const bool drawn = cull == twin::Cull::none || (cull == twin::Cull::back) == order.front;
      int pixels = 0;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          if (!covered(*image, x, y)) continue;
          ++pixels;
          EXPECT_EQ(rgba_at(*image, x, y), (order.front ? Pixel{1, 0, 0, 1} : Pixel{0, 1, 0, 1}))
              << "pixel " << x << "," << y;
        }
      // The triangle covers half of a 12x12 square.
      EXPECT_EQ(pixels > 60, drawn) << "cull " << int(cull) << ", " << pixels << " pixels";
    }
  }
}

// gl_ClipDistance and gl_CullDistance drop a triangle with every corner outside a plane;
// a clip plane through a triangle is an error (the reference rasteriser does not cut
// triangles), never an image drawn as if unclipped.
TEST(TwinExecution, ClipAndCullDistancesDropWholeTriangles) {
  constexpr int width = 16, height = 8;
  const auto vertex_writing = [](const std::string& statement) {
    return "#version 450\nlayout(location = 0) in vec4 position;\nvoid main() {\n  gl_Position = position;\n  " +
           statement + "\n}\n";
  };
  const std::string fragment = fragment_shader("", "colour = vec4(1.0);");
  // Left of x = 0 and right of it, apart.
  const Mesh left_and_right{.streams = {{.location = 0,
                                         .values = {-0.9, -0.9, 0.5, 1, -0.1, -0.9, 0.5, 1, -0.5, 0.9, 0.5, 1,
                                                    0.1, -0.9, 0.5, 1, 0.9, -0.9, 0.5, 1, 0.5, 0.9, 0.5, 1}}},
                            .vertex_count = 6,
                            .indices = {0, 1, 2, 3, 4, 5}};
  Mesh right_only = left_and_right;
  right_only.indices = {3, 4, 5};
  auto plain = glsl_program(pass_through_vertex, fragment);
  ASSERT_TRUE(plain) << plain.error();
  auto right_image = draw_mesh(*plain, right_only, {}, width, height);
  auto quad_image = draw_quad(*plain, {}, width, height);
  ASSERT_TRUE(right_image && quad_image);

  struct Case {
    std::string statement;
    bool quad;                       // the full-screen quad, else the two triangles
    const twin::TwinImage* expected;   // null: an error
  };
  for (const Case& c : {Case{"gl_ClipDistance[0] = position.x + 2.0;", true, &*quad_image},
                        Case{"gl_ClipDistance[0] = position.x;", false, &*right_image},
                        Case{"gl_CullDistance[0] = position.x;", false, &*right_image},
                        Case{"gl_CullDistance[0] = position.x;", true, &*quad_image},
                        Case{"gl_ClipDistance[0] = position.x;", true, nullptr}}) {
    SCOPED_TRACE(c.statement + (c.quad ? " on the quad" : " on two triangles"));
    auto program = glsl_program(vertex_writing(c.statement), fragment);
    ASSERT_TRUE(program) << program.error();
    auto image = draw_mesh(*program, c.quad ? full_screen_quad() : left_and_right, {}, width, height);
    if (!c.expected) {
      ASSERT_FALSE(image);
      EXPECT_NE(image.error().message.find("gl_ClipDistance"), std::string::npos) << image.error().to_string();
      continue;
    }
    ASSERT_TRUE(image) << image.error().to_string();
    EXPECT_EQ(image->coverage, c.expected->coverage);
    EXPECT_EQ(image->rgba, c.expected->rgba);
  }
}

// ---------------------------------------------------------------------------------------
// 8. Textures

TEST(TwinExecution, TextureSamplingFetchAndSize) {
  constexpr int width = 8, height = 8;
  // A 4x4 RGBA float texture with a 2x2 level 1; every texel tells where it is.
  std::vector<float> level0, level1;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) level0.insert(level0.end(), {float(i), float(j), float(i + 4 * j), 0.5f});
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) level1.insert(level1.end(), {float(100 + i), float(200 + j), 0.0f, 1.0f});
  twin::TextureImage texture{.dimensions = 2, .width = 4, .height = 4, .channels = 4};
  texture.levels = {level0, level1};
  const auto texel = [&](int level, int i, int j) -> Pixel {
    const std::vector<float>& data = level == 0 ? level0 : level1;
    const size_t at = size_t(j * (level == 0 ? 4 : 2) + i) * 4;
    return {data[at], data[at + 1], data[at + 2], data[at + 3]};
  };
  twin::SamplerState nearest;
  nearest.min_filter = nearest.mag_filter = twin::Filter::nearest;
  nearest.mip_filter = twin::MipFilter::nearest;
  twin::SamplerState linear;   // linear filters, no mips, clamped

  // Binding 0: a combined image-sampler (nearest); 1: the texture alone (its own state
  // linear, which must not count); 2: a nearest sampler alone; 3: the combined texture
  // with the linear state.
  twin::BoundResources resources;
  resources.resources = {{&texture, nearest}, {&texture, linear}, {nullptr, nearest}};
  resources.handles = {{{0, 0}, 0}, {{0, 1}, 1}, {{0, 2}, 2}, {{0, 3}, 1}};
  const std::string declarations = R"(
layout(set = 0, binding = 0) uniform sampler2D tex;
layout(set = 0, binding = 1) uniform texture2D colour_map;
layout(set = 0, binding = 2) uniform sampler nearest_sampler;
layout(set = 0, binding = 3) uniform sampler2D smooth_tex;
)";
  const std::string prelude = "vec2 uv = gl_FragCoord.xy / 8.0;\n";
  // uv * 4 = (p + 0.5) / 2: level 0 texel p / 2; level 1 texel p / 4.
  const auto level0_at = [&](double x, double y) { return texel(0, int(x) / 2, int(y) / 2); };
  const auto level1_at = [&](double x, double y) { return texel(1, int(x) / 4, int(y) / 4); };
  // Bilinear with clamp to edge on level 0, by hand.
  const auto bilinear = [&](double s, double t) {
    const double u = s * 4 - 0.5, v = t * 4 - 0.5;
    const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
    const double a = u - i0, b = v - j0;
    const auto clamped = [&](int i, int j) { return texel(0, std::clamp(i, 0, 3), std::clamp(j, 0, 3)); };
    Pixel out{};
    for (size_t c = 0; c < 4; ++c)
      out[c] = (1 - a) * (1 - b) * clamped(i0, j0)[c] + a * (1 - b) * clamped(i0 + 1, j0)[c] +
               (1 - a) * b * clamped(i0, j0 + 1)[c] + a * b * clamped(i0 + 1, j0 + 1)[c];
    return out;
  };
  const std::vector<FragmentCase> cases = {
      // Implicit LOD: the texture is half the image's size, so magnification on level 0.
      {prelude + "colour = texture(tex, uv);", level0_at},
      {prelude + "colour = textureLod(tex, uv, 1.0);", level1_at},
      // Bias 2 on lambda -1; gradients of 2 texels per pixel; projection by q = 2.
      {prelude + "colour = texture(tex, uv, 2.0);", level1_at},
      {prelude + "colour = textureGrad(tex, uv, vec2(0.5, 0.0), vec2(0.0, 0.25));", level1_at},
      {prelude + "colour = textureProj(tex, vec3(uv * 2.0, 2.0));", level0_at},
      {"colour = texelFetch(tex, ivec2(gl_FragCoord.xy) % 4, 0);",
       [&](double x, double y) { return texel(0, int(x) % 4, int(y) % 4); }},
      {"colour = texelFetch(tex, ivec2(gl_FragCoord.xy) / 2 % 2, 1);",
       [&](double x, double y) { return texel(1, int(x) / 2 % 2, int(y) / 2 % 2); }},
      {"colour = vec4(textureSize(tex, 0), textureSize(tex, 1)) + vec4(0, 0, 0, 10 * textureQueryLevels(tex));",
       [](double, double) -> Pixel { return {4, 4, 2, 22}; }},
      {prelude + "colour = texture(smooth_tex, uv * 0.875 + 0.03125);",
       [&](double x, double y) { return bilinear(x / 8 * 0.875 + 0.03125, y / 8 * 0.875 + 0.03125); }},
      // A separate texture and sampler: the sampler's state filters.
      {prelude + "colour = texture(sampler2D(colour_map, nearest_sampler), uv);", level0_at},
      {prelude + "colour = textureLod(sampler2D(colour_map, nearest_sampler), uv, 1.0);", level1_at},
      {"colour = texelFetch(sampler2D(colour_map, nearest_sampler), ivec2(gl_FragCoord.xy) % 4, 0);",
       [&](double x, double y) { return texel(0, int(x) % 4, int(y) % 4); }},
  };
  check_fragment_cases(declarations, cases, width, height, resources, 1e-12);
}

// ---------------------------------------------------------------------------------------
// 9. Precision: the float and half twins

// Every float-typed value the fragment stage computes at a pixel.
class FloatValues : public twin::Observer {
 public:
  explicit FloatValues(const twin::Module& module) : module_(module) {}
  void value(uint32_t instruction, std::span<const double> values) override {
    const twin::Instruction& in = module_.instructions[instruction];
    const twin::Type* t = &module_.types[in.result_type];
    while (t->kind == twin::Type::Kind::vector || t->kind == twin::Type::Kind::matrix) t = &module_.types[t->element];
    if (t->kind == twin::Type::Kind::floating) all.insert(all.end(), values.begin(), values.end());
  }
  std::vector<double> all;

 private:
  const twin::Module& module_;
};

bool is_float(double x) { return std::isnan(x) || double(float(x)) == x; }
bool is_half(double x) { return std::isnan(x) || twin::round_to_half(x) == x; }

TEST(TwinExecution, FloatTwinRoundsEveryResultToBinary32) {
  constexpr int width = 12, height = 10;
  const std::string body = R"(
float x = gl_FragCoord.x, y = gl_FragCoord.y;
float a = x / 3.0 + y / 7.0;
float b = sin(a) * exp(y * 0.1) + sqrt(x);
vec3 n = normalize(vec3(a, b, 1.0));
colour = vec4(n * 1.1, b / 3.0 + pow(a, 0.3));
)";
  auto program = glsl_program(pass_through_vertex, fragment_shader("", body));
  ASSERT_TRUE(program) << program.error();
  auto exact = draw_quad(*program, {}, width, height);
  auto single = draw_quad(*program, {}, width, height, {.precision = twin::Precision::single});
  ASSERT_TRUE(exact) << exact.error().to_string();
  ASSERT_TRUE(single) << single.error().to_string();
  int rounded = 0;
  for (size_t i = 0; i < single->rgba.size(); ++i) {
    EXPECT_TRUE(is_float(single->rgba[i])) << "value " << i << ": " << single->rgba[i];
    EXPECT_NEAR(single->rgba[i], exact->rgba[i], 1e-5 * std::max(1.0, std::fabs(exact->rgba[i])));
    if (single->rgba[i] != exact->rgba[i]) ++rounded;
  }
  EXPECT_GT(rounded, 0) << "the float twin gives the double twin's results";
  // Every intermediate too, at a few pixels.
  const Mesh quad = full_screen_quad();
  const twin::BoundResources no_resources;
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{5, 3}, std::pair{11, 9}}) {
    FloatValues observed(*program->fragment);
    const twin::DrawInput input{.program = *program,
                                .resources = no_resources,
                                .streams = quad.streams,
                                .vertex_count = quad.vertex_count,
                                .indices = quad.indices,
                                .width = width,
                                .height = height,
                                .precision = twin::Precision::single};
    ASSERT_TRUE(twin::trace_pixel(input, x, y, observed));
    EXPECT_GT(observed.all.size(), 10u);
    for (double v : observed.all) EXPECT_TRUE(is_float(v)) << v << " at pixel " << x << "," << y;
  }
}

TEST(TwinExecution, HalfTwinRoundsMediumpOnly) {
  const std::string declarations = R"(
layout(set = 0, binding = 0) uniform Values { float one; float tiny; } u;
)";
  // 1 + 2^-12 needs 13 significant bits: binary32 holds it, binary16 (11 bits) rounds to 1.
  const std::string body = R"(
mediump float a = u.one;
mediump float t = u.tiny;
mediump float relaxed_sum = a + t;
highp float ha = u.one;
highp float ht = u.tiny;
highp float full_sum = ha + ht;
mediump float x = gl_FragCoord.x;
mediump float relaxed_scaled = (a + t * x) * 3.0;
mediump int count = int(gl_FragCoord.x) * 1000 + 1;
highp int exact_count = count;
colour = vec4(relaxed_sum, full_sum, relaxed_scaled, float(exact_count));
)";
  auto program = glsl_program(pass_through_vertex, fragment_shader(declarations, body));
  ASSERT_TRUE(program) << program.error();
  BlockBytes block(8);
  block.put_float(0, 1.0f);
  block.put_float(4, 1.0f / 4096);
  twin::BoundResources resources;
  resources.buffers[{0, 0}] = {block.bytes(), {}};
  constexpr int width = 8, height = 4;
  constexpr double sum = 1.000244140625;
  for (const twin::Precision precision : {twin::Precision::exact, twin::Precision::single, twin::Precision::half}) {
    SCOPED_TRACE(twin::to_string(precision));
    auto image = draw_quad(*program, resources, width, height, {.precision = precision});
    ASSERT_TRUE(image) << image.error().to_string();
    const bool half = precision == twin::Precision::half;
    expect_every_pixel(
        *image,
        [&](double x, double) -> Pixel {
          const double t = 1.0 / 4096;
          // The half twin rounds each mediump step: t * x, the sum, the product.
          const double scaled = half ? twin::round_to_half(twin::round_to_half(1 + twin::round_to_half(t * x)) * 3)
                                     : (1 + t * x) * 3;
          // A mediump int is a 16-bit integer on a GPU: exact in range, never a binary16 float.
          return {half ? 1.0 : sum, sum, scaled, std::trunc(x) * 1000 + 1};
        },
        0);
    if (half) {
      for (int x = 0; x < width; ++x) EXPECT_TRUE(is_half(rgba_at(*image, x, 0)[2]));
    }
  }
}

// ---------------------------------------------------------------------------------------
// 10. Errors are values

// A copy of `spirv` with OpLine `file`:`line` before the first instruction `op` (and the
// OpString it names), as a compile with debug information would have it.
std::vector<uint32_t> with_line_before(const std::vector<uint32_t>& spirv, spv::Op op, const std::string& file,
                                       uint32_t line) {
  std::vector<uint32_t> out(spirv.begin(), spirv.begin() + 5);
  const uint32_t string_id = out[3]++;   // a new id: the old bound
  std::vector<uint32_t> op_string = {0, string_id};
  for (size_t i = 0; i <= file.size(); i += 4) {
    uint32_t word = 0;
    for (size_t b = 0; b < 4 && i + b < file.size(); ++b) word |= uint32_t(uint8_t(file[i + b])) << (8 * b);
    op_string.push_back(word);
  }
  op_string[0] = uint32_t(op_string.size()) << 16 | uint32_t(spv::Op::OpString);
  const std::vector<uint32_t> op_line = {4u << 16 | uint32_t(spv::Op::OpLine), string_id, line, 1};
  bool string_placed = false, line_placed = false;
  for (size_t at = 5; at < spirv.size();) {
    const auto this_op = spv::Op(spirv[at] & 0xffff);
    const size_t words = spirv[at] >> 16;
    // OpString opens the debug section, after the entry points and execution modes.
    const bool preamble = this_op == spv::Op::OpCapability || this_op == spv::Op::OpExtension ||
                          this_op == spv::Op::OpExtInstImport || this_op == spv::Op::OpMemoryModel ||
                          this_op == spv::Op::OpEntryPoint || this_op == spv::Op::OpExecutionMode ||
                          this_op == spv::Op::OpExecutionModeId;
    if (!preamble && !string_placed) {
      out.insert(out.end(), op_string.begin(), op_string.end());
      string_placed = true;
    }
    if (this_op == op && !line_placed) {
      out.insert(out.end(), op_line.begin(), op_line.end());
      line_placed = true;
    }
    out.insert(out.end(), spirv.begin() + std::ptrdiff_t(at), spirv.begin() + std::ptrdiff_t(at + words));
    at += words;
  }
  return out;
}

TEST(TwinExecution, UnsupportedInstructionIsAnErrorNamingItAndItsLine) {
  // clockARB() reads a device timer (OpReadClockKHR): nothing a CPU twin can reproduce.
  const std::string fragment = R"(#version 450
#extension GL_ARB_shader_clock : require
layout(location = 0) out vec4 colour;
void main() {
  uvec2 clock = clock2x32ARB();
  colour = vec4(float(clock.x & 1u));
}
)";
  auto vertex_spirv = glsl_spirv(shaderbed::Stage::vertex, pass_through_vertex);
  auto fragment_spirv = glsl_spirv(shaderbed::Stage::fragment, fragment);
  ASSERT_TRUE(vertex_spirv) << vertex_spirv.error();
  ASSERT_TRUE(fragment_spirv) << fragment_spirv.error();
  const std::vector<uint32_t> with_line = with_line_before(*fragment_spirv, spv::Op::OpReadClockKHR, "clock.frag", 5);
  for (const bool lines : {false, true}) {
    // The compile stage's own OpLine names test.frag; the inserted one names clock.frag.
    SCOPED_TRACE(lines ? "with an inserted OpLine" : "with the compile stage's OpLine");
    auto program = twin::load_program(*vertex_spirv, "main", lines ? with_line : *fragment_spirv, "main");
    ASSERT_TRUE(program) << program.error().to_string();
    auto image = draw_quad(*program, {}, 4, 4);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().message.find("OpReadClockKHR"), std::string::npos) << image.error().to_string();
    EXPECT_EQ(image.error().file, lines ? "clock.frag" : "test.frag");
    EXPECT_EQ(image.error().line, 5);
  }
}

TEST(TwinExecution, BuiltInTheTwinDoesNotProvideIsAnError) {
  // gl_PrimitiveID in a fragment shader comes from the geometry stage's capability.
  auto program = glsl_program(pass_through_vertex, fragment_shader("", "colour = vec4(float(gl_PrimitiveID));"));
  ASSERT_TRUE(program) << program.error();
  auto image = draw_quad(*program, {}, 4, 4);
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("gl_PrimitiveID"), std::string::npos) << image.error().to_string();
}

TEST(TwinExecution, MissingBindingsAreErrorsNamingTheVariable) {
  struct Missing {
    std::string declarations, body, name;
  };
  const std::vector<Missing> cases = {
      {"layout(set = 0, binding = 3) uniform Params { vec4 tint; } params;", "colour = params.tint;", "params"},
      // An anonymous block's variable has no name of its own: the block's type name says which.
      {"layout(set = 1, binding = 2) uniform Material { vec4 albedo; };", "colour = albedo;", "Material"},
      {"layout(set = 0, binding = 1) uniform sampler2D albedo_map;", "colour = texture(albedo_map, vec2(0.5));",
       "albedo_map"},
  };
  for (const Missing& c : cases) {
    SCOPED_TRACE(c.declarations);
    auto program = glsl_program(pass_through_vertex, fragment_shader(c.declarations, c.body));
    ASSERT_TRUE(program) << program.error();
    auto image = draw_quad(*program, {}, 4, 4);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().message.find(c.name), std::string::npos) << image.error().to_string();
  }
}

TEST(TwinExecution, ShortVertexStreamIsAnError) {
  auto program = glsl_program(pass_through_vertex, fragment_shader("", "colour = vec4(1.0);"));
  ASSERT_TRUE(program) << program.error();
  Mesh quad = full_screen_quad();
  quad.streams[0].values.resize(3 * 4);   // three vertices' values for four vertices
  auto image = draw_mesh(*program, quad, {}, 4, 4);
  ASSERT_FALSE(image);
  EXPECT_NE(image.error().message.find("position (location 0)"), std::string::npos) << image.error().to_string();
}

// ---------------------------------------------------------------------------------------
// 11. trace_pixel

// Every value reported, by instruction, in the order computed.
class RecordedValues : public twin::Observer {
 public:
  void value(uint32_t instruction, std::span<const double> values) override {
    by_instruction[instruction].emplace_back(values.begin(), values.end());
  }
  std::map<uint32_t, std::vector<std::vector<double>>> by_instruction;
};

// The index of the instruction whose result the shader stores into the variable named `name`.
std::optional<uint32_t> instruction_stored_into(const twin::Module& m, const std::string& name) {
  uint32_t variable = 0;
  for (const auto& [id, n] : m.names)
    if (n == name) variable = id;
  for (const twin::Instruction& in : m.instructions) {
    if (spv::Op(in.op) != spv::Op::OpStore || m.operands_of(in)[0] != variable) continue;
    const uint32_t value = m.operands_of(in)[1];
    for (uint32_t i = 0; i < m.instructions.size(); ++i)
      if (m.instructions[i].result == value) return i;
  }
  return std::nullopt;
}

TEST(TwinExecution, TracePixelReportsTheFragmentsOwnValues) {
  const std::string body = R"(
float doubled = gl_FragCoord.x * 2.0;
float shifted = doubled + gl_FragCoord.y;
if (gl_FragCoord.x > 4.0) {
  float tripled = gl_FragCoord.x * 3.0;
  shifted += tripled;
}
colour = vec4(shifted);
)";
  auto program = glsl_program(pass_through_vertex, fragment_shader("", body));
  ASSERT_TRUE(program) << program.error();
  const twin::Module& m = *program->fragment;
  const auto doubled = instruction_stored_into(m, "doubled"), shifted = instruction_stored_into(m, "shifted"),
             tripled = instruction_stored_into(m, "tripled");
  ASSERT_TRUE(doubled && shifted && tripled);
  const Mesh quad = full_screen_quad();
  const twin::BoundResources resources;
  const twin::DrawInput input{.program = *program,
                              .resources = resources,
                              .streams = quad.streams,
                              .vertex_count = quad.vertex_count,
                              .indices = quad.indices,
                              .width = 10,
                              .height = 6};
  // (3, 1) is the top-right lane of its quad, (6, 4) the bottom-left of another; only the
  // second takes the branch.
  for (const auto& [x, y] : {std::pair{3, 1}, std::pair{6, 4}}) {
    SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
    RecordedValues recorded;
    ASSERT_TRUE(twin::trace_pixel(input, x, y, recorded));
    const double fx = x + 0.5, fy = y + 0.5;
    ASSERT_EQ(recorded.by_instruction[*doubled], (std::vector<std::vector<double>>{{2 * fx}}));
    ASSERT_EQ(recorded.by_instruction[*shifted], (std::vector<std::vector<double>>{{2 * fx + fy}}));
    if (fx > 4) {
      EXPECT_EQ(recorded.by_instruction[*tripled], (std::vector<std::vector<double>>{{3 * fx}}));
    } else {
      EXPECT_EQ(recorded.by_instruction.count(*tripled), 0u) << "a value of a branch the pixel did not take";
    }
  }
  // Outside the drawn triangles there is nothing to trace.
  const Mesh corner{.streams = {{.location = 0, .values = {-1, -1, 0.5, 1, 0, -1, 0.5, 1, -1, 0, 0.5, 1}}},
                    .vertex_count = 3,
                    .indices = {0, 1, 2}};
  const twin::DrawInput partial{.program = *program,
                                .resources = resources,
                                .streams = corner.streams,
                                .vertex_count = corner.vertex_count,
                                .indices = corner.indices,
                                .width = 10,
                                .height = 6};
  RecordedValues none;
  const auto uncovered = twin::trace_pixel(partial, 0, 0, none);
  EXPECT_FALSE(uncovered);
  EXPECT_TRUE(none.by_instruction.empty());
}

}  // namespace
}  // namespace twin_tests
