// The quad-precision run that checks the double twin itself (twin::wide_pixel): equal where
// double is exact enough, and it exposes the double twin's own cancellation error.
#include <gtest/gtest.h>

#include <cmath>

#include "TwinTestSupport.h"

namespace {

using namespace twin_tests;

twin::DrawInput quad_input(const twin::Program& program, const twin::BoundResources& resources, const Mesh& mesh) {
  return twin::DrawInput{.program = program,
                         .resources = resources,
                         .streams = mesh.streams,
                         .vertex_count = mesh.vertex_count,
                         .indices = mesh.indices,
                         .width = 8,
                         .height = 8,
                         .precision = twin::Precision::exact,
                         .threads = 1};
}

TEST(WidePixel, AgreesWithTheDoubleTwinOnAWellConditionedShader) {
  auto program = glsl_program(pass_through_vertex, R"(#version 450
layout(location = 0) out vec4 colour;
void main() {
  float x = gl_FragCoord.x / 8.0;
  colour = vec4(sqrt(x) * exp(-x), pow(x, 2.5), sin(x), 1.0);
}
)");
  ASSERT_TRUE(program) << program.error();
  const Mesh mesh = full_screen_quad();
  const twin::BoundResources resources;
  const twin::DrawInput input = quad_input(*program, resources, mesh);
  auto image = twin::draw(input);
  ASSERT_TRUE(image) << image.error().to_string();
  for (int x : {0, 3, 7}) {
    auto wide = twin::wide_pixel(input, x, 5);
    ASSERT_TRUE(wide) << wide.error().to_string();
    const auto exact = rgba_at(*image, x, 5);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR((*wide)[size_t(c)], exact[size_t(c)], 1e-15) << x << "," << c;
  }
}

TEST(WidePixel, ExposesTheDoubleTwinsOwnCancellation) {
  // (x + 2^40) - 2^40 keeps x's bits above 2^-12 in double and above 2^-72 in the quad.
  auto program = glsl_program(pass_through_vertex, R"(#version 450
layout(location = 0) out vec4 colour;
void main() {
  float x = gl_FragCoord.x / 1000.0;
  float big = 1099511627776.0;
  colour = vec4((x + big) - big, x, 0.0, 1.0);
}
)");
  ASSERT_TRUE(program) << program.error();
  const Mesh mesh = full_screen_quad();
  const twin::BoundResources resources;
  const twin::DrawInput input = quad_input(*program, resources, mesh);
  auto image = twin::draw(input);
  ASSERT_TRUE(image) << image.error().to_string();
  const auto exact = rgba_at(*image, 3, 2);   // x = 3.5 / 1000
  auto wide = twin::wide_pixel(input, 3, 2);
  ASSERT_TRUE(wide) << wide.error().to_string();
  const double x = exact[1];
  EXPECT_GT(std::fabs(exact[0] - x), 1e-6);       // double lost the digits below 2^-12
  EXPECT_LT(std::fabs((*wide)[0] - x), 1e-15);    // the quad kept them
  EXPECT_GT(std::fabs((*wide)[0] - exact[0]), 1e-6);
}

}  // namespace
