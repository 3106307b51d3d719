// Every GL path (native GLSL, GL_ARB_gl_spirv, SPIRV-Cross GLSL) must draw the same
// pixels: exact float values without clamping, NaN/Inf kept, the documented coverage,
// row 0 at the top, uniforms reaching the shader, and missing uniforms reported.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

constexpr int kWidth = 64;   // not square, so a swapped width/height shows
constexpr int kHeight = 32;

const char* const kConstantFragment = R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(0.25, 1.5, -2.0, 1.0); }
)";

const char* const kNonFiniteFragment = R"(#version 450
layout(location = 0) out vec4 colour;
void main() {
  colour = vec4(uintBitsToFloat(0x7fc00000u), uintBitsToFloat(0x7f800000u), uintBitsToFloat(0xff800000u), 1.0);
}
)";

const char* const kTexcoordVertex = R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texcoord;
layout(location = 0) out vec2 surface_uv;
void main() { surface_uv = texcoord; gl_Position = vec4(position, 1.0); }
)";

const char* const kTexcoordFragment = R"(#version 450
layout(location = 0) in vec2 surface_uv;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(surface_uv, 0.0, 1.0); }
)";

struct PixelRect {
  int x0, y0, x1, y1;  // inclusive-exclusive, image rows (0 = top)
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  int area() const { return (x1 - x0) * (y1 - y0); }
};

class GlPath : public ::testing::TestWithParam<ShaderPath> {
 protected:
  Result<RenderOutput> draw(const std::string& vertex, const std::string& fragment, const Mesh& mesh,
                            const UniformResolver& uniforms, int width = kWidth, int height = kHeight) {
    auto backend = gl_backend();
    if (!backend) return std::unexpected(backend.error());
    auto compiled = compile_glsl(vertex, fragment);
    if (!compiled) return std::unexpected(compiled.error());
    program_ = std::move(*compiled);
    return (*backend)->render(DrawJob{.program = program_, .path = GetParam(), .mesh = mesh, .uniforms = uniforms,
                                      .width = width, .height = height});
  }

  // Inside: covered and exactly `rgba`; outside: uncovered and the clear colour.
  static void expect_only(const Image& image, PixelRect rect, const float (&rgba)[4]) {
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    int mismatches = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const bool inside = rect.contains(x, y);
        const float* p = image.pixel(x, y);
        const float* want = inside ? rgba : (const float[4]){0, 0, 0, 0};
        const bool ok = image.covered(x, y) == inside && p[0] == want[0] && p[1] == want[1] && p[2] == want[2] &&
                        p[3] == want[3];
        if (!ok && ++mismatches <= 5)
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") covered=" << int(image.covered(x, y)) << " rgba=("
                        << p[0] << ", " << p[1] << ", " << p[2] << ", " << p[3] << "), expected "
                        << (inside ? "inside" : "outside");
      }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(coverage_count(image), rect.area());
  }

  CompiledProgram program_;
};

TEST_P(GlPath, WritesFloatValuesExactlyWithoutClamping) {
  // Upper half of NDC, middle half of x: columns 16..47, image rows 0..15 (the top).
  const Mesh mesh = ndc_rectangle(-0.5f, 0.0f, 0.5f, 1.0f);
  auto out = draw(kPassThroughVertex, kConstantFragment, mesh, MapResolver{});
  ASSERT_TRUE(out) << out.error().to_string();
  expect_only(out->image, {16, 0, 48, 16}, {0.25f, 1.5f, -2.0f, 1.0f});
}

TEST_P(GlPath, KeepsNanAndInfinity) {
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  auto out = draw(kPassThroughVertex, kNonFiniteFragment, mesh, MapResolver{});
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(10, 10);
  EXPECT_TRUE(std::isnan(p[0])) << p[0];
  EXPECT_TRUE(std::isinf(p[1]) && p[1] > 0) << p[1];
  EXPECT_TRUE(std::isinf(p[2]) && p[2] < 0) << p[2];
  EXPECT_EQ(p[3], 1.0f);
  EXPECT_EQ(coverage_count(out->image), kWidth * kHeight);
}

TEST_P(GlPath, UpperHalfOfClipSpaceIsTheTopOfTheImage) {
  // A triangle entirely above y = 0.5 in NDC: only image rows 0..7 may be touched.
  Mesh mesh = ndc_rectangle(-1, 0.5f, 1, 1);
  mesh.indices = {0, 1, 2};  // the lower-right half of that strip
  auto out = draw(kPassThroughVertex, kConstantFragment, mesh, MapResolver{});
  ASSERT_TRUE(out) << out.error().to_string();
  int top = 0, elsewhere = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) (y < 8 ? top : elsewhere) += out->image.covered(x, y);
  EXPECT_GT(top, 0);
  EXPECT_EQ(elsewhere, 0);
  // The triangle (-1,0.5)-(1,0.5)-(1,1) is full width at its bottom edge (image row 7)
  // and only its right-hand tip reaches the top row: a mirrored image fails here.
  EXPECT_TRUE(out->image.covered(kWidth - 1, 0));
  EXPECT_FALSE(out->image.covered(0, 0));
  EXPECT_TRUE(out->image.covered(kWidth / 2, 7));
  EXPECT_FALSE(out->image.covered(kWidth / 2, 0));
}

TEST_P(GlPath, UniformBlocksReachBothStages) {
  // clip = M * v with M translating by (+0.5, -0.5): the rectangle x -0.5..0.5, y 0..1
  // lands on x 0..1, y -0.5..0.5 (columns 32..63, rows 8..23). A transposed upload puts
  // the translation into w instead and the rectangle lands elsewhere.
  const Mesh mesh = ndc_rectangle(-0.5f, 0.0f, 0.5f, 1.0f);
  const MapResolver uniforms({
      {"clip_from_object", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, -0.5f, 0, 1}},
      {"tint", {0.5f, 3.0f, -4.0f, 2.0f}},
      {"scale", {0.5f}},
  });
  auto out = draw(kTransformVertex, kMaterialFragment, mesh, uniforms);
  ASSERT_TRUE(out) << out.error().to_string();
  expect_only(out->image, {32, 8, 64, 24}, {0.25f, 1.5f, -2.0f, 1.0f});
}

TEST_P(GlPath, MissingUniformIsAnErrorNamingIt) {
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  const MapResolver uniforms({
      {"clip_from_object", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
      {"tint", {1, 1, 1, 1}},
  });
  auto out = draw(kTransformVertex, kMaterialFragment, mesh, uniforms);
  ASSERT_FALSE(out);
  const Error& e = out.error();
  EXPECT_NE(e.message.find("'scale'"), std::string::npos) << e.to_string();
  EXPECT_NE(e.message.find("Material"), std::string::npos) << e.to_string();
  EXPECT_NE(e.message.find(to_string(GetParam())), std::string::npos) << e.to_string();
  EXPECT_EQ(e.backend, "gl");
}

TEST_P(GlPath, FeedsTexcoordsByNameAndLinksVaryings) {
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  auto out = draw(kTexcoordVertex, kTexcoordFragment, mesh, MapResolver{});
  ASSERT_TRUE(out) << out.error().to_string();
  // uv (0,0) is the bottom-left corner of the mesh = bottom-left of the image.
  const float* top_left = out->image.pixel(0, 0);
  const float* bottom_right = out->image.pixel(kWidth - 1, kHeight - 1);
  EXPECT_NEAR(top_left[0], 0.5f / kWidth, 1e-5f);
  EXPECT_NEAR(top_left[1], 1.0f - 0.5f / kHeight, 1e-5f);
  EXPECT_NEAR(bottom_right[0], 1.0f - 0.5f / kWidth, 1e-5f);
  EXPECT_NEAR(bottom_right[1], 0.5f / kHeight, 1e-5f);
}

TEST_P(GlPath, DepthTestKeepsTheNearerSurface) {
  // Two overlapping rectangles in one mesh; the far one is drawn last and must lose.
  Mesh near = ndc_rectangle(-1, -1, 1, 1, 0.25f), far = ndc_rectangle(-1, -1, 1, 1, 0.75f);
  Mesh both = near;
  for (uint32_t i : far.indices) both.indices.push_back(i + uint32_t(near.vertices.size()));
  both.vertices.insert(both.vertices.end(), far.vertices.begin(), far.vertices.end());
  const char* depth_as_colour = R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(gl_FragCoord.z); }
)";
  auto out = draw(kPassThroughVertex, depth_as_colour, both, MapResolver{});
  ASSERT_TRUE(out) << out.error().to_string();
  // Depth range [0, 1] (glClipControl zero-to-one): NDC z = 0.25 is window depth 0.25.
  EXPECT_EQ(out->image.pixel(5, 5)[0], 0.25f);
}

TEST_P(GlPath, ReportsTimings) {
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  auto out = draw(kPassThroughVertex, kConstantFragment, mesh, MapResolver{}, 256, 256);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_GT(out->timings.build_ms, 0.0);
  EXPECT_GT(out->timings.draw_ms, 0.0);
  EXPECT_GT(out->timings.readback_ms, 0.0);
  RecordProperty("build_ms", std::to_string(out->timings.build_ms));
  RecordProperty("draw_ms", std::to_string(out->timings.draw_ms));
  RecordProperty("readback_ms", std::to_string(out->timings.readback_ms));
  std::printf("[ timing   ] %s 256x256: build %.3f ms, draw %.3f ms, readback %.3f ms\n", to_string(GetParam()),
              out->timings.build_ms, out->timings.draw_ms, out->timings.readback_ms);
}

INSTANTIATE_TEST_SUITE_P(AllGlslPaths, GlPath,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace shaderbed::gl_test
