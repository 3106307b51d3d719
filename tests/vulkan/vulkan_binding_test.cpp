// Uniform blocks from the resolver to the shader: values arrive, several sets and both
// stages bind, and every way a binding can be wrong is an Error that says what.
#include "VulkanTestSupport.h"

namespace shaderbed::vulkan_test {
namespace {

const std::string tinted_fragment_shader = R"(#version 450
layout(set = 0, binding = 0) uniform Material { vec4 tint; float gain; };
layout(location = 0) out vec4 colour;
void main() { colour = tint * gain; }
)";

TEST(VulkanBinding, UniformBlockValueReachesTheShader) {
  auto program = compile_glsl(passthrough_vertex_shader, tinted_fragment_shader);
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver uniforms({{"tint", {0.125f, 2.5f, -7.0f, 0.5f}}, {"gain", {2.0f}}});
  auto out = draw(*program, full_screen_quad(), uniforms, 8, 8);
  ASSERT_TRUE(out) << out.error().to_string();
  const float* p = out->image.pixel(4, 4);
  EXPECT_EQ(p[0], 0.25f);
  EXPECT_EQ(p[1], 5.0f);
  EXPECT_EQ(p[2], -14.0f);
  EXPECT_EQ(p[3], 1.0f);
}

TEST(VulkanBinding, BlocksInSeveralSetsAndBothStagesBind) {
  // Vertex stage: a matrix in set 2 (sets 0 and 1 of the vertex stage unused there) moves
  // the quad; fragment stage: set 0 and a block shared by both stages in set 1.
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec3 position;
layout(set = 2, binding = 3) uniform Transform { mat4 clip_from_object; };
layout(set = 1, binding = 0) uniform Shared { vec4 shared_value; };
layout(location = 0) out float from_vertex;
void main() { gl_Position = clip_from_object * vec4(position, 1.0); from_vertex = shared_value.x; }
)",
                              R"(#version 450
layout(set = 0, binding = 0) uniform Material { vec4 tint; };
layout(set = 1, binding = 0) uniform Shared { vec4 shared_value; };
layout(location = 0) in float from_vertex;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(tint.x, shared_value.y, from_vertex, 1.0); }
)");
  ASSERT_TRUE(program) << program.error().to_string();
  constexpr int size = 16;
  // Column-major translation by (+0.5, 0) in NDC: the left-half quad moves to the middle.
  const std::vector<float> translate = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
  const MapResolver uniforms(
      {{"clip_from_object", translate}, {"tint", {3.0f, 0, 0, 0}}, {"shared_value", {0.5f, -4.0f, 0, 0}}});
  auto out = draw(*program, pixel_rect_quad(0, 0, 8, 16, size, size), uniforms, size, size);
  ASSERT_TRUE(out) << out.error().to_string();
  EXPECT_EQ(covered_pixel_count(out->image), 8u * 16u);
  EXPECT_FALSE(out->image.covered(3, 8));
  EXPECT_TRUE(out->image.covered(4, 8));
  EXPECT_TRUE(out->image.covered(11, 8));
  EXPECT_FALSE(out->image.covered(12, 8));
  const float* p = out->image.pixel(8, 8);
  EXPECT_EQ(p[0], 3.0f);
  EXPECT_EQ(p[1], -4.0f);
  EXPECT_EQ(p[2], 0.5f);
}

TEST(VulkanBinding, MissingUniformIsAnErrorNamingIt) {
  auto program = compile_glsl(passthrough_vertex_shader, tinted_fragment_shader);
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver uniforms({{"tint", {1, 1, 1, 1}}});  // no "gain"
  auto out = draw(*program, full_screen_quad(), uniforms);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'gain'"), std::string::npos) << text;
  EXPECT_NE(text.find("'Material'"), std::string::npos) << text;
  EXPECT_EQ(out.error().stage, ErrorStage::bind) << text;  // the resolver's stage is kept
}

TEST(VulkanBinding, DifferentBlocksAtTheSameBindingAreAnError) {
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec3 position;
layout(set = 0, binding = 0) uniform Transform { vec4 offset; };
void main() { gl_Position = vec4(position, 1.0) + offset; }
)",
                              tinted_fragment_shader);
  ASSERT_TRUE(program) << program.error().to_string();
  // The compile stage may move fragment bindings (a per-stage binding base for GL), so
  // the clash is made in the reflection, which is all the check looks at; it fails
  // before the SPIR-V is used.
  ASSERT_EQ(program->vertex.reflection.uniform_blocks.size(), 1u);
  ASSERT_EQ(program->fragment.reflection.uniform_blocks.size(), 1u);
  const UniformBlock& transform = program->vertex.reflection.uniform_blocks[0];
  UniformBlock& material = program->fragment.reflection.uniform_blocks[0];
  material.set = transform.set;
  material.binding = transform.binding;
  const MapResolver uniforms({{"offset", {0, 0, 0, 0}}, {"tint", {1, 1, 1, 1}}, {"gain", {1}}});
  auto out = draw(*program, full_screen_quad(), uniforms);
  ASSERT_FALSE(out);
  const std::string text = out.error().to_string();
  EXPECT_NE(text.find("'Transform' and 'Material'"), std::string::npos) << text;
  EXPECT_EQ(out.error().stage, ErrorStage::vulkan) << text;
}

TEST(VulkanBinding, VertexInputThatIsNoMeshStreamIsAnError) {
  auto program = compile_glsl(R"(#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 bone_weights;
void main() { gl_Position = vec4(position, 1.0) + bone_weights; }
)",
                              constant_fragment_shader("vec4(1.0)"));
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver no_uniforms;
  auto out = draw(*program, full_screen_quad(), no_uniforms);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("bone_weights"), std::string::npos) << out.error().to_string();
}

}  // namespace
}  // namespace shaderbed::vulkan_test
