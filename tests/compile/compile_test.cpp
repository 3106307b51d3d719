// The compile stage on real glslang / SPIRV-Tools / SPIRV-Cross.
#include <filesystem>

#include <gtest/gtest.h>

#include "ReflectionLookup.h"
#include "SourceTree.h"
#include "compile/Compiler.h"
#include "compile/SpirvTools.h"

namespace shaderbed {
namespace {

using test::find_member;
using test::kShaders;

ShaderSource source(Stage stage, std::string text, std::string path = "test.shader") {
  return ShaderSource{.stage = stage, .path = std::move(path), .text = std::move(text)};
}

TEST(Compile, EveryLibraryShaderCompilesForBothTargets) {
  int compiled = 0;
  for (const char* dir : {"hlsl", "glsl"})
    for (const auto& entry : std::filesystem::directory_iterator(kShaders / dir)) {
      const std::string ext = entry.path().extension().string();
      const std::string name = entry.path().filename().string();
      const Stage stage = (ext == ".frag" || name.find("_ps") != std::string::npos) ? Stage::fragment : Stage::vertex;
      auto src = load_shader_source(stage, entry.path().string());
      ASSERT_TRUE(src) << src.error().to_string();
      for (Target target : {Target::vulkan, Target::opengl}) {
        auto m = compile_stage(std::string(dir) == "hlsl" ? Language::hlsl : Language::glsl, *src, target);
        ASSERT_TRUE(m) << m.error().to_string();
        EXPECT_FALSE(m->spirv.empty());
        ++compiled;
      }
    }
  EXPECT_GE(compiled, 2 * 14);
}

TEST(Compile, GlslErrorCarriesFileAndLine) {
  auto m = compile_stage(Language::glsl,
                         source(Stage::fragment,
                                "#version 450\n"
                                "layout(location = 0) out vec4 c;\n"
                                "void main() {\n"
                                "  c = vec4(undefined_name);\n"
                                "}\n",
                                "broken.frag"),
                         Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, "broken.frag");
  EXPECT_EQ(m.error().line, 4);
  EXPECT_NE(m.error().message.find("undefined_name"), std::string::npos) << m.error().message;
}

TEST(Compile, HlslErrorCarriesFileAndLine) {
  auto m = compile_stage(Language::hlsl,
                         source(Stage::fragment,
                                "float3 LightVector : register(c4);\n"
                                "\n"
                                "float4 main(float3 n : TEXCOORD1) : COLOR0\n"
                                "{\n"
                                "    return float4(dot(LightVector, n) +, 1);\n"
                                "}\n",
                                "broken.hlsl"),
                         Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, "broken.hlsl");
  EXPECT_EQ(m.error().line, 5);
}

TEST(Compile, HlslRegistersBecomeByteOffsets) {
  auto src = load_shader_source(Stage::vertex, (kShaders / "hlsl" / "phong_vs.hlsl").string());
  ASSERT_TRUE(src);
  auto m = compile_stage(Language::hlsl, *src, Target::vulkan);
  ASSERT_TRUE(m) << m.error().to_string();
  const UniformMember* transform = find_member(m->reflection, "Transform");
  const UniformMember* light = find_member(m->reflection, "LightVector");
  const UniformMember* specular = find_member(m->reflection, "SpecularColor");
  ASSERT_TRUE(transform && light && specular);
  EXPECT_EQ(transform->offset, 0u);
  EXPECT_EQ(light->offset, 4u * 16);     // register(c4)
  EXPECT_EQ(specular->offset, 8u * 16);  // register(c8)
  EXPECT_EQ(transform->columns, 4u);
  EXPECT_TRUE(transform->column_registers) << "HLSL default packing keeps a column per register";
}

TEST(Compile, HlslVertexInputsKeepTheirSemantics) {
  auto src = load_shader_source(Stage::vertex, (kShaders / "hlsl" / "setup_vs.hlsl").string());
  ASSERT_TRUE(src);
  auto m = compile_stage(Language::hlsl, *src, Target::vulkan);
  ASSERT_TRUE(m) << m.error().to_string();
  ASSERT_EQ(m->reflection.inputs.size(), 2u);
  EXPECT_EQ(m->reflection.inputs[0].semantic, "SV_POSITION") << "POSITION is #defined to SV_Position";
  EXPECT_EQ(m->reflection.inputs[1].semantic, "NORMAL");
}

TEST(Compile, HlslStagesGetDistinctBindings) {
  ProgramSource p{Language::hlsl, *load_shader_source(Stage::vertex, (kShaders / "hlsl" / "setup_vs.hlsl").string()),
                  *load_shader_source(Stage::fragment, (kShaders / "hlsl" / "phong_ps.hlsl").string())};
  auto program = compile_program(p);
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->vertex.reflection.uniform_blocks.size(), 1u);
  ASSERT_EQ(program->fragment.reflection.uniform_blocks.size(), 1u);
  EXPECT_NE(program->vertex_gl.reflection.uniform_blocks[0].binding,
            program->fragment_gl.reflection.uniform_blocks[0].binding);
  // The GL cross-compiled sources name their blocks per stage so they can link.
  EXPECT_NE(program->vertex_cross_glsl.find("_vs"), std::string::npos);
  EXPECT_NE(program->fragment_cross_glsl.find("_fs"), std::string::npos);
  EXPECT_NE(program->fragment_cross_glsl.find("sb_varying1"), std::string::npos) << program->fragment_cross_glsl;
}

TEST(Compile, OptimizerShrinksAModule) {
  auto src = load_shader_source(Stage::fragment, (kShaders / "glsl" / "phong.frag").string());
  ASSERT_TRUE(src);
  auto m = compile_stage(Language::glsl, *src, Target::vulkan);
  ASSERT_TRUE(m);
  auto optimized = optimize_spirv(m->spirv, Target::vulkan, OptimizeLevel::size);
  ASSERT_TRUE(optimized) << optimized.error().to_string();
  EXPECT_LT(optimized->size(), m->spirv.size());
  EXPECT_NE(disassemble(*optimized).find("OpEntryPoint"), std::string::npos);
}

TEST(Compile, HlslNoiseIsAnErrorNotACrash) {
  auto m = compile_stage(Language::hlsl,
                         source(Stage::fragment,
                                "// noise(x) in a comment is fine\n"
                                "float noise_scale : register(c4);\n"
                                "float4 main(float3 p : TEXCOORD0) : COLOR0\n"
                                "{\n"
                                "    return float4(noise(p) * noise_scale, 0, 0, 1);\n"
                                "}\n",
                                "noisy.hlsl"),
                         Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().line, 5);
  EXPECT_NE(m.error().message.find("noise"), std::string::npos);
}

TEST(Compile, MissingFileIsAnErrorWithThePath) {
  auto src = load_shader_source(Stage::vertex, "/nonexistent/shader.vert");
  ASSERT_FALSE(src);
  EXPECT_EQ(src.error().file, "/nonexistent/shader.vert");
}

}  // namespace
}  // namespace shaderbed
