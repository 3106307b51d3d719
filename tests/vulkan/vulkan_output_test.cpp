// What the backend reads back: exact unclamped floats, non-finite values, coverage from
// the depth buffer, image orientation, the depth test and the vertex streams.
#include <cmath>

#include "VulkanTestSupport.h"

namespace shaderbed::vulkan_test {
namespace {

TEST(VulkanOutput, ColourIsReadBackExactlyAndUnclamped) {
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(0.25, 1.5, -2.0, 1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, full_screen_quad(), no_uniforms, 32, 16);
  ASSERT_TRUE(out) << out.error().to_string();
  ASSERT_EQ(out->image.width, 32);
  ASSERT_EQ(out->image.height, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      const float* p = out->image.pixel(x, y);
      ASSERT_EQ(p[0], 0.25f) << "at " << x << "," << y;
      ASSERT_EQ(p[1], 1.5f) << "at " << x << "," << y;
      ASSERT_EQ(p[2], -2.0f) << "at " << x << "," << y;
      ASSERT_EQ(p[3], 1.0f) << "at " << x << "," << y;
      ASSERT_TRUE(out->image.covered(x, y)) << "at " << x << "," << y;
    }
}

TEST(VulkanOutput, NonFiniteValuesSurvive) {
  // Bit patterns, so no compiler can fold them into something finite.
  auto program = compile_glsl(passthrough_vertex_shader,
                              constant_fragment_shader("vec4(uintBitsToFloat(0x7fc00000u), uintBitsToFloat(0x7f800000u), "
                                                       "uintBitsToFloat(0xff800000u), 3.0e38)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, full_screen_quad(), no_uniforms, 8, 8);
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(3, 5);
  EXPECT_TRUE(std::isnan(p[0])) << p[0];
  EXPECT_TRUE(std::isinf(p[1]) && p[1] > 0) << p[1];
  EXPECT_TRUE(std::isinf(p[2]) && p[2] < 0) << p[2];
  EXPECT_EQ(p[3], 3.0e38f);
}

TEST(VulkanOutput, CoverageIsExactlyThePixelRectangle) {
  constexpr int width = 40, height = 30;
  constexpr int x0 = 5, y0 = 3, x1 = 17, y1 = 25;  // 12 x 22 pixels
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, pixel_rect_quad(x0, y0, x1, y1, width, height), no_uniforms, width, height);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(covered_pixel_count(out->image), size_t((x1 - x0) * (y1 - y0)));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool inside = x >= x0 && x < x1 && y >= y0 && y < y1;
      ASSERT_EQ(out->image.covered(x, y), inside) << "at " << x << "," << y;
      // Uncovered pixels keep the clear colour (0,0,0,0); covered ones the shader's.
      ASSERT_EQ(out->image.pixel(x, y)[3], inside ? 1.0f : 0.0f) << "at " << x << "," << y;
    }
}

TEST(VulkanOutput, PositiveNdcYIsTheTopOfTheImage) {
  constexpr int size = 32;
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  Mesh upper_triangle;
  upper_triangle.name = "upper triangle";
  upper_triangle.vertices = {vertex_at(-0.9f, 0.1f, 0.5f), vertex_at(0.9f, 0.1f, 0.5f), vertex_at(0.0f, 0.9f, 0.5f)};
  upper_triangle.indices = {0, 1, 2};
  const MapResolver no_uniforms;
  auto out = draw(*program, upper_triangle, no_uniforms, size, size);
  ASSERT_TRUE(out) << out.error().to_string();
  size_t upper = 0, lower = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) (y < size / 2 ? upper : lower) += out->image.covered(x, y);
  EXPECT_GT(upper, 100u);
  EXPECT_EQ(lower, 0u);
  // The apex (NDC y = 0.9) is near row 0: its row is narrower than the base's.
  auto row_width = [&](int y) {
    int n = 0;
    for (int x = 0; x < size; ++x) n += out->image.covered(x, y);
    return n;
  };
  EXPECT_LT(row_width(3), row_width(13));
}

TEST(VulkanOutput, NearerSurfaceWinsWhicheverIsDrawnFirst) {
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 0) out float depth;
void main() { gl_Position = vec4(position, 1.0); depth = position.z; }
)",
                              R"(#version 450
layout(location = 0) in float depth;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(depth, 0.0, 0.0, 1.0); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  for (bool near_first : {true, false}) {
    Mesh near = full_screen_quad(0.25f), far = full_screen_quad(0.75f);
    Mesh both = near_first ? near : far;
    const Mesh& second = near_first ? far : near;
    for (uint32_t i : second.indices) both.indices.push_back(i + 4);
    both.vertices.insert(both.vertices.end(), second.vertices.begin(), second.vertices.end());
    auto out = draw(*program, both, no_uniforms, 16, 16);
    ASSERT_TRUE(out) << out.error().to_string();
    EXPECT_EQ(out->image.pixel(7, 9)[0], 0.25f) << (near_first ? "near drawn first" : "far drawn first");
  }
}

TEST(VulkanOutput, MeshStreamsReachTheirInputsAndWIsFilledWithOne) {
  // vec4 position: the mesh stores xyz and the driver must supply w = 1, else the quad
  // would land elsewhere. Normal, tangent and uv go to locations the shader chose.
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 3) in vec2 texcoord;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 tangent;
layout(location = 0) out vec4 streams;
void main() { gl_Position = position; streams = vec4(normal.y, tangent.z, texcoord); }
)",
                              R"(#version 450
layout(location = 0) in vec4 streams;
layout(location = 0) out vec4 colour;
void main() { colour = streams; }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  constexpr int size = 20;
  Mesh quad = pixel_rect_quad(4, 6, 14, 16, size, size);
  for (Vertex& v : quad.vertices) {
    v.normal = {0.0f, -0.625f, 0.0f};
    v.tangent = {0.0f, 0.0f, 0.375f};
    v.uv = {0.75f, 0.125f};
  }
  const MapResolver no_uniforms;
  auto out = draw(*program, quad, no_uniforms, size, size);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(covered_pixel_count(out->image), 100u);
  EXPECT_TRUE(out->image.covered(4, 6));
  EXPECT_TRUE(out->image.covered(13, 15));
  // Attributes equal at every vertex interpolate to the same value, within rounding.
  const float* p = out->image.pixel(9, 11);
  EXPECT_NEAR(p[0], -0.625f, 1e-6f);
  EXPECT_NEAR(p[1], 0.375f, 1e-6f);
  EXPECT_NEAR(p[2], 0.75f, 1e-6f);
  EXPECT_NEAR(p[3], 0.125f, 1e-6f);
}

}  // namespace
}  // namespace shaderbed::vulkan_test
