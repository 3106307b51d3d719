// The SPIR-V and SPIRV-Cross paths bind from the compile stage's reflection; the backend
// must notice when that reflection cannot be trusted rather than draw wrong values.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

const MapResolver kValues({
    {"clip_from_object", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
    {"tint", {1, 1, 1, 1}},
    {"scale", {1}},
});

Result<RenderOutput> render_reflected(const CompiledProgram& program, ShaderPath path) {
  auto backend = gl_backend();
  if (!backend) return std::unexpected(backend.error());
  const Mesh mesh = ndc_rectangle(-1, -1, 1, 1);
  return (*backend)->render(
      DrawJob{.program = program, .path = path, .mesh = mesh, .uniforms = kValues, .width = 8, .height = 8});
}

UniformMember& member_named(UniformBlock& block, const std::string& name) {
  for (UniformMember& m : block.members)
    if (m.name == name) return m;
  throw std::runtime_error("no member " + name);
}

TEST(GlReflection, CrossGlslLayoutThatDisagreesWithReflectionIsAnError) {
  auto program = compile_glsl(kTransformVertex, kMaterialFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_TRUE(render_reflected(*program, ShaderPath::cross_glsl)) << "the untouched program must draw";

  ASSERT_EQ(program->fragment_gl.reflection.uniform_blocks.size(), 1u);
  member_named(program->fragment_gl.reflection.uniform_blocks[0], "scale").offset += 4;
  auto out = render_reflected(*program, ShaderPath::cross_glsl);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("'scale'"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("offset"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("cross path"), std::string::npos) << out.error().to_string();
}

TEST(GlReflection, TwoDifferentBlocksOnOneBindingIsAnError) {
  auto program = compile_glsl(kTransformVertex, kMaterialFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  // As if both stages' blocks had been given the same GL binding.
  program->fragment_gl.reflection.uniform_blocks[0].binding = program->vertex_gl.reflection.uniform_blocks[0].binding;
  auto out = render_reflected(*program, ShaderPath::spirv);
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("Transform"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("Material"), std::string::npos) << out.error().to_string();
  EXPECT_NE(out.error().message.find("binding"), std::string::npos) << out.error().to_string();
}

TEST(GlReflection, WrongEntryPointIsAnErrorOnTheSpirvPath) {
  auto program = compile_glsl(kTransformVertex, kMaterialFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  program->fragment_gl.entry_point = "not_there";
  auto out = render_reflected(*program, ShaderPath::spirv);
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().file, "test.frag");
  EXPECT_NE(out.error().message.find("not_there"), std::string::npos) << out.error().to_string();
}

}  // namespace
}  // namespace shaderbed::gl_test
