// The backend as a whole: identity, input checks that must be errors rather than
// crashes, render targets of several sizes, timings.
#include <cstdio>

#include "VulkanTestSupport.h"
#include "backends/vulkan/VulkanRenderer.h"

namespace shaderbed::vulkan_test {
namespace {

TEST(VulkanBackend, IsLavapipeAndTakesSpirvOnly) {
  Backend* backend = shared_backend();
  ASSERT_NE(backend, nullptr);
  EXPECT_EQ(backend->name(), "vulkan");
  const std::string version = backend->driver_version();
  EXPECT_NE(version.find("llvmpipe"), std::string::npos) << version;
  EXPECT_NE(version.find("Mesa"), std::string::npos) << version;
  for (Language language : {Language::glsl, Language::hlsl, Language::cg})
    EXPECT_EQ(backend->paths(language), std::vector<ShaderPath>{ShaderPath::spirv});
}

TEST(VulkanBackend, OtherShaderPathsAreAnError) {
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, full_screen_quad(), no_uniforms, 8, 8, ShaderPath::native_glsl);
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().stage, "vulkan");
  EXPECT_NE(out.error().message.find("SPIR-V"), std::string::npos) << out.error().to_string();
}

TEST(VulkanBackend, BadInputsAreErrorsNotCrashes) {
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;

  Mesh out_of_range = full_screen_quad();
  out_of_range.indices.back() = 4;
  auto bad_index = draw(*program, out_of_range, no_uniforms);
  ASSERT_FALSE(bad_index);
  EXPECT_NE(bad_index.error().message.find("index"), std::string::npos) << bad_index.error().to_string();

  Mesh empty;
  EXPECT_FALSE(draw(*program, empty, no_uniforms));
  EXPECT_FALSE(draw(*program, full_screen_quad(), no_uniforms, 0, 8));
  EXPECT_FALSE(draw(*program, full_screen_quad(), no_uniforms, 8, 1 << 20));

  CompiledProgram no_spirv = *program;
  no_spirv.fragment.spirv.clear();
  auto missing = draw(no_spirv, full_screen_quad(), no_uniforms);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().file, "test.frag") << missing.error().to_string();

  CompiledProgram wrong_entry = *program;
  wrong_entry.vertex.entry_point = "VertexMain";
  auto entry = draw(wrong_entry, full_screen_quad(), no_uniforms);
  ASSERT_FALSE(entry);
  EXPECT_NE(entry.error().message.find("'VertexMain'"), std::string::npos) << entry.error().to_string();

  // After all of that the backend still draws.
  auto fine = draw(*program, full_screen_quad(), no_uniforms, 8, 8);
  ASSERT_TRUE(fine) << fine.error().to_string();
  EXPECT_EQ(covered_pixel_count(fine->image), 64u);
}

TEST(VulkanBackend, SizesChangeBetweenDraws) {
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(0.5)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  struct Size {
    int width, height;
  };
  for (Size size : {Size{24, 10}, Size{7, 33}, Size{24, 10}, Size{1, 1}}) {
    // The left half of the image, whatever its size (odd widths: the pixels whose
    // centres lie left of the middle).
    auto out = draw(*program, ndc_quad(-1.0f, -1.0f, 0.0f, 1.0f), no_uniforms, size.width, size.height);
    ASSERT_TRUE(out) << out.error().to_string();
    ASSERT_EQ(out->image.width, size.width);
    ASSERT_EQ(out->image.height, size.height);
    EXPECT_EQ(covered_pixel_count(out->image), size_t(size.width / 2) * size.height)
        << size.width << "x" << size.height;
  }
}

TEST(VulkanBackend, TimingsAreMeasuredFor256Square) {
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(0.25, 1.5, -2.0, 1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, full_screen_quad(), no_uniforms, 256, 256);
  ASSERT_TRUE(out) << out.error().to_string();
  const RenderTimings& t = out->timings;
  EXPECT_GT(t.build_ms, 0.0);
  EXPECT_GT(t.draw_ms, 0.0);
  EXPECT_GT(t.readback_ms, 0.0);
  auto* renderer = dynamic_cast<vulkan::VulkanRenderer*>(shared_backend());
  ASSERT_NE(renderer, nullptr);
  ASSERT_TRUE(renderer->last_gpu_draw_ms().has_value());
  EXPECT_GE(*renderer->last_gpu_draw_ms(), 0.0);
  EXPECT_LE(*renderer->last_gpu_draw_ms(), t.draw_ms);
  std::printf("256x256 quad: build %.3f ms, draw %.3f ms (timestamps %.3f ms), readback %.3f ms\n", t.build_ms,
              t.draw_ms, *renderer->last_gpu_draw_ms(), t.readback_ms);
}

}  // namespace
}  // namespace shaderbed::vulkan_test
