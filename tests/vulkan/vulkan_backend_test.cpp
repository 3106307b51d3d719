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
  EXPECT_EQ(out.error().stage, ErrorStage::vulkan);
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

TEST(VulkanBackend, APipelineIsBuiltOnceAndTimedDrawsAreRepeated) {
  // A colour no other test uses, so this program's pipeline cannot be in the cache yet.
  auto program = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(0.25, 1.5, -2.0, 0.125)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  const Mesh quad = full_screen_quad();
  Backend* backend = shared_backend();
  ASSERT_NE(backend, nullptr);
  const DrawJob job{.program = *program, .path = ShaderPath::spirv, .mesh = quad, .uniforms = no_uniforms,
                    .width = 256, .height = 256, .timing = {.warmup = 1, .runs = 4}};
  auto first = backend->render(job);
  ASSERT_TRUE(first) << first.error().to_string();
  auto second = backend->render(job);
  ASSERT_TRUE(second) << second.error().to_string();

  EXPECT_FALSE(first->timings.program_cached);
  EXPECT_GT(first->timings.build_ms, 0.0);
  EXPECT_TRUE(second->timings.program_cached);
  EXPECT_EQ(second->timings.build_ms, 0.0);
  EXPECT_EQ(first->image.rgba, second->image.rgba);   // the cached pipeline draws the same image
  for (const RenderTimings* t : {&first->timings, &second->timings}) {
    EXPECT_EQ(t->gpu_clock, "timestamp queries");
    ASSERT_EQ(t->gpu_ms.size(), 4u);
    ASSERT_EQ(t->wall_ms.size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_GT(t->gpu_ms[i], 0.0);
      // The timestamps bracket work that submit + wait also waited for.
      EXPECT_LE(t->gpu_ms[i], t->wall_ms[i]);
    }
  }
  std::printf("256x256 quad: build %.3f ms, draw %.3f ms, timestamps %.3f ms, readback %.3f ms\n",
              first->timings.build_ms, first->timings.draw_ms, first->timings.gpu_ms[0], first->timings.readback_ms);

  // Another program (even one differing only in a constant) is another pipeline.
  auto other = compile_glsl(passthrough_vertex_shader, constant_fragment_shader("vec4(0.25, 1.5, -2.0, 0.25)"));
  ASSERT_TRUE(other) << other.error().to_string();
  auto third = backend->render(DrawJob{.program = *other, .path = ShaderPath::spirv, .mesh = quad,
                                       .uniforms = no_uniforms, .width = 256, .height = 256});
  ASSERT_TRUE(third) << third.error().to_string();
  EXPECT_FALSE(third->timings.program_cached);
  EXPECT_TRUE(third->timings.gpu_ms.empty());   // runs = 0: not timed
  EXPECT_EQ(third->image.rgba[3], 0.25f);
}

}  // namespace
}  // namespace shaderbed::vulkan_test
