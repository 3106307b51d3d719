// GLSL as GL authors write it, on real glslang: the legacy-GLSL dialect layer
// (compile/LegacyGlsl.h) maps each GL-era built-in to a uniform, input or output
// reflected under its legacy name and keeps the author's line numbers; GLSL 3.30 loose
// uniforms compile under glslang's relaxed Vulkan rules; varyings declared in different
// orders link by name (compile/GlslVaryings.h); glslang's #version error is the one
// reported; Vulkan GLSL is marked as not applying to the native GL path.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/GlslProfile.h"
#include "compile/GlslVaryings.h"
#include "compile/LegacyGlsl.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

ShaderSource glsl_source(Stage stage, std::string text, std::string path) {
  return ShaderSource{.stage = stage, .path = std::move(path), .text = std::move(text)};
}

Result<CompiledProgram> compile_glsl(std::string vertex, std::string fragment) {
  return compile_program(ProgramSource{.language = Language::glsl,
                                       .vertex = glsl_source(Stage::vertex, std::move(vertex), "author.vert"),
                                       .fragment = glsl_source(Stage::fragment, std::move(fragment), "author.frag")});
}

std::set<std::string> member_names(const Reflection& r) {
  std::set<std::string> names;
  for (const UniformBlock& b : r.uniform_blocks)
    for (const UniformMember& m : b.members) names.insert(m.name);
  return names;
}

const char* kPassThroughFragment =
    "varying vec4 color;\n"
    "void main() { gl_FragColor = color; }\n";

TEST(LegacyGlsl, EveryBuiltinBecomesAUniformOrInputUnderItsLegacyName) {
  const char* vertex =
      "varying vec4 color;\n"
      "void main() {\n"
      "  vec4 p = gl_ModelViewMatrix * gl_Vertex;\n"
      "  vec3 n = gl_NormalMatrix * gl_Normal;\n"
      "  vec4 l = gl_LightSource[0].position + gl_LightSource[0].diffuse + gl_LightSource[0].specular\n"
      "         + gl_LightSource[0].ambient + vec4(gl_LightSource[0].spotDirection, gl_LightSource[0].spotExponent)\n"
      "         + vec4(gl_LightSource[0].spotCosCutoff + gl_LightSource[0].constantAttenuation\n"
      "                + gl_LightSource[0].linearAttenuation + gl_LightSource[0].quadraticAttenuation);\n"
      "  vec4 m = gl_FrontMaterial.emission + gl_FrontMaterial.ambient + gl_FrontMaterial.diffuse\n"
      "         + gl_FrontMaterial.specular * gl_FrontMaterial.shininess + gl_LightModel.ambient;\n"
      "  vec4 products = gl_FrontLightProduct[0].ambient + gl_FrontLightProduct[0].diffuse\n"
      "                + gl_FrontLightProduct[0].specular + gl_FrontLightModelProduct.sceneColor;\n"
      "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
      "  color = p + vec4(n, 1.0) + l + m + products + gl_Color + gl_ProjectionMatrix * p\n"
      "        + gl_ModelViewProjectionMatrixInverse * p + gl_ModelViewMatrixInverseTranspose * p;\n"
      "  gl_Position = ftransform();\n"
      "}\n";
  auto program = compile_glsl(vertex, kPassThroughFragment);
  ASSERT_TRUE(program) << program.error().to_string();
  const std::set<std::string> names = member_names(program->vertex.reflection);
  for (const char* expected :
       {"gl_ModelViewMatrix", "gl_NormalMatrix", "gl_ProjectionMatrix", "gl_ModelViewProjectionMatrix",
        "gl_ModelViewProjectionMatrixInverse", "gl_ModelViewMatrixInverseTranspose", "gl_LightSource[0].position",
        "gl_LightSource[0].diffuse", "gl_LightSource[0].specular", "gl_LightSource[0].ambient",
        "gl_LightSource[0].spotDirection", "gl_LightSource[0].spotExponent", "gl_LightSource[0].spotCutoff",
        "gl_LightSource[0].constantAttenuation", "gl_LightSource[0].linearAttenuation",
        "gl_LightSource[0].quadraticAttenuation", "gl_FrontMaterial.emission", "gl_FrontMaterial.ambient",
        "gl_FrontMaterial.diffuse", "gl_FrontMaterial.specular", "gl_FrontMaterial.shininess",
        "gl_LightModel.ambient"})
    EXPECT_TRUE(names.contains(expected)) << expected;
  for (const std::string& name : names) EXPECT_FALSE(name.starts_with("sb")) << name;
  std::set<std::string> inputs;
  for (const StageInput& in : program->vertex.reflection.inputs) inputs.insert(in.name);
  EXPECT_EQ(inputs, (std::set<std::string>{"gl_Vertex", "gl_Normal", "gl_MultiTexCoord0", "gl_Color"}));
  // The GL-target module carries the same names (the gl/spirv and gl/cross paths bind by them).
  EXPECT_EQ(member_names(program->vertex_gl.reflection), names);
  EXPECT_TRUE(program->native_glsl_compatibility);
  EXPECT_EQ(program->vertex_native_glsl, vertex);   // the native path gets the author's text
}

TEST(LegacyGlsl, MatricesDefaultToTheScenesAndLightStateHasNoDefault) {
  EXPECT_EQ(legacy_glsl_default_binding("gl_ModelViewMatrix"), "world_view");
  EXPECT_EQ(legacy_glsl_default_binding("gl_ProjectionMatrix"), "projection");
  EXPECT_EQ(legacy_glsl_default_binding("gl_ModelViewProjectionMatrix"), "transform");
  EXPECT_EQ(legacy_glsl_default_binding("gl_NormalMatrix"), "normal_matrix_view");
  EXPECT_EQ(legacy_glsl_default_binding("gl_ModelViewMatrixInverse"), "world_view_inverse");
  EXPECT_EQ(legacy_glsl_default_binding("gl_ProjectionMatrixTranspose"), "projection_transpose");
  EXPECT_EQ(legacy_glsl_default_binding("gl_ModelViewProjectionMatrixInverseTranspose"), "transform_inverse_transpose");
  EXPECT_EQ(legacy_glsl_default_binding("gl_LightSource[0].diffuse"), std::nullopt);
  EXPECT_EQ(legacy_glsl_default_binding("gl_FrontMaterial.shininess"), std::nullopt);
  EXPECT_EQ(legacy_glsl_default_binding("gl_ModelViewMatrixSquared"), std::nullopt);
}

TEST(LegacyGlsl, FragmentBuiltinsBecomeOutputsAndTextureLookupsTheirModernNames) {
  const char* fragment =
      "#version 120\n"
      "uniform sampler2D texture;\n"   // a keyword-free name in 1.20, a built-in function in 4.50
      "void main() {\n"
      "  gl_FragData[0] = texture2D(texture, gl_TexCoord[0].st) * gl_Color;\n"
      "}\n";
  const char* vertex =
      "#version 120\n"
      "void main() { gl_FrontColor = gl_Color; gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }\n";
  auto program = compile_glsl(vertex, fragment);
  ASSERT_TRUE(program) << program.error().to_string();
  ASSERT_EQ(program->fragment.reflection.samplers.size(), 1u);
  EXPECT_EQ(program->fragment.reflection.samplers[0].name, "texture");
}

// An error in the author's code is reported at the author's line, with or without #version.
TEST(LegacyGlsl, AnErrorInTheAuthorsShaderIsAtTheAuthorsLine) {
  for (const std::string header : {"", "// a comment before the version\n#version 110\n", "#version 130 compatibility\n"}) {
    const int first_code_line = int(std::count(header.begin(), header.end(), '\n')) + 1;
    const std::string vertex = header +
                               "varying vec3 n;\n"
                               "void main() {\n"
                               "  n = gl_Normal;\n"
                               "  gl_Position = ftransform() + undeclared_thing;\n"
                               "}\n";
    auto program = compile_glsl(vertex, "varying vec3 n;\nvoid main() { gl_FragColor = vec4(n, 1.0); }\n");
    ASSERT_FALSE(program) << header;
    EXPECT_EQ(program.error().file, "author.vert");
    EXPECT_EQ(program.error().line, first_code_line + 3) << header << program.error().to_string();
    EXPECT_NE(program.error().message.find("undeclared_thing"), std::string::npos) << program.error().message;
  }
}

TEST(LegacyGlsl, AnUnsupportedBuiltinIsOneErrorNamingItAndItsLine) {
  auto program = compile_glsl(
      "void main() {\n"
      "  gl_Position = ftransform();\n"
      "  gl_FrontSecondaryColor = gl_SecondaryColor;\n"
      "}\n",
      "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_FALSE(program);
  EXPECT_EQ(program.error().line, 3);
  EXPECT_NE(program.error().message.find("gl_FrontSecondaryColor"), std::string::npos) << program.error().message;

  auto indexed = compile_glsl("uniform int i;\nvoid main() { gl_Position = gl_LightSource[i].position; }\n",
                              "void main() { gl_FragColor = vec4(1.0); }\n");
  ASSERT_FALSE(indexed);
  EXPECT_EQ(indexed.error().line, 2);
  EXPECT_NE(indexed.error().message.find("literal"), std::string::npos) << indexed.error().message;
}

// Without the dialect (one stage straight to glslang) a GL-era shader fails on its
// #version: that message, at the directive's line, not the "'varying' : Reserved word" after it.
TEST(LegacyGlsl, GlslangsVersionErrorIsTheOneReported) {
  auto module = compile_stage(Language::glsl,
                              glsl_source(Stage::vertex, "// old\n#version 120\nvarying vec3 n;\nvoid main() { n = gl_Normal; }\n",
                                     "old.vert"),
                              Target::vulkan);
  ASSERT_FALSE(module);
  EXPECT_TRUE(module.error().message.starts_with("#version")) << module.error().message;
  EXPECT_EQ(module.error().line, 2);
}

TEST(LegacyGlsl, VersionsAndProfilesAreRecognised) {
  EXPECT_TRUE(is_legacy_glsl(glsl_version("void main() {}")));
  EXPECT_TRUE(is_legacy_glsl(glsl_version("/* c */\n#version 140\n")));
  EXPECT_TRUE(is_legacy_glsl(glsl_version("#version 330 compatibility\n")));
  EXPECT_FALSE(is_legacy_glsl(glsl_version("#version 330 core\n")));
  EXPECT_FALSE(is_legacy_glsl(glsl_version("#version 450\n")));
  EXPECT_FALSE(is_legacy_glsl(glsl_version("#version 100 es\n")));
  EXPECT_EQ(glsl_version("/* c */\n#version 140\n").line, 2);
}

TEST(RelaxedGlsl, LooseUniformsComeInOneBlockPerStageWithDistinctBindings) {
  const char* vertex =
      "#version 330 core\n"
      "layout (location = 0) in vec3 aPos;\n"
      "uniform mat4 model, view;\n"
      "uniform mat4 projection;\n"
      "void main() { gl_Position = projection * view * model * vec4(aPos, 1.0); }\n";
  const char* fragment =
      "#version 330 core\n"
      "out vec4 FragColor;\n"
      "uniform vec3 objectColor;\n"
      "void main() { FragColor = vec4(objectColor, 1.0); }\n";
  auto program = compile_glsl(vertex, fragment);
  ASSERT_TRUE(program) << program.error().to_string();
  for (const ShaderModule* m : {&program->vertex, &program->vertex_gl}) {
    ASSERT_EQ(m->reflection.uniform_blocks.size(), 1u);
    const UniformBlock& block = m->reflection.uniform_blocks[0];
    ASSERT_EQ(block.members.size(), 3u);
    EXPECT_EQ(block.members[0].name, "model");
    EXPECT_EQ(block.members[1].name, "view");
    EXPECT_EQ(block.members[1].offset, 64u);
    EXPECT_EQ(block.members[2].name, "projection");
  }
  ASSERT_EQ(program->fragment.reflection.uniform_blocks.size(), 1u);
  EXPECT_NE(program->fragment.reflection.uniform_blocks[0].binding, program->vertex.reflection.uniform_blocks[0].binding);
  EXPECT_FALSE(program->native_glsl_compatibility);
  EXPECT_TRUE(program->native_glsl_skip_reason.empty());
}

TEST(RelaxedGlsl, OnlyShadersWithLooseUniformsTakeTheRelaxedRules) {
  EXPECT_TRUE(needs_relaxed_vulkan_rules("uniform mat4 model;"));
  EXPECT_TRUE(needs_relaxed_vulkan_rules("layout(location = 2) uniform highp vec3 a, b;"));
  EXPECT_FALSE(needs_relaxed_vulkan_rules("uniform sampler2D t; layout(binding = 0) uniform B { mat4 m; };"));
  EXPECT_FALSE(needs_relaxed_vulkan_rules("void f(float uniform_value) { }"));
}

// GL links varyings by name; SPIR-V by location. Declared in a different order in each
// stage, with one more in the vertex shader, they still meet.
TEST(GlslVaryings, FragmentInputsTakeTheLocationOfTheVertexOutputOfTheirName) {
  auto sources = assign_varying_locations(
      glsl_source(Stage::vertex, "out vec3 Normal;\nout vec2 Extra;\nsmooth out vec3 FragPos, Tint;\nout mat3 Basis;\n", "v"),
      glsl_source(Stage::fragment, "in vec3 FragPos;\nin mat3 Basis;\nin vec3 Normal;\nin vec3 Tint;\n", "f"));
  ASSERT_TRUE(sources) << sources.error().to_string();
  EXPECT_EQ(sources->vertex,
            "layout(location = 0) out vec3 Normal;\nlayout(location = 1) out vec2 Extra;\n"
            "layout(location = 2) smooth out vec3 FragPos; layout(location = 3) smooth out vec3 Tint;\n"
            "layout(location = 4) out mat3 Basis;\n");
  EXPECT_EQ(sources->fragment,
            "layout(location = 2) in vec3 FragPos;\nlayout(location = 4) in mat3 Basis;\n"
            "layout(location = 0) in vec3 Normal;\nlayout(location = 3) in vec3 Tint;\n");
}

// The library's GLSL declares every location: its SPIR-V must not change.
TEST(GlslVaryings, ShadersWithLocationsEverywhereAreUnchanged) {
  int checked = 0;
  for (const fs::directory_entry& file : fs::directory_iterator(fs::path(SHADERBED_SOURCE_DIR) / "shaders" / "glsl")) {
    const std::string name = file.path().filename().string();
    std::ifstream in(file.path());
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_FALSE(needs_relaxed_vulkan_rules(text.str())) << name;
    ++checked;
    const Stage stage = name.ends_with(".vert") ? Stage::vertex : Stage::fragment;
    auto same = assign_varying_locations(glsl_source(stage, text.str(), name), glsl_source(stage, text.str(), name));
    ASSERT_TRUE(same) << same.error().to_string();
    EXPECT_EQ(stage == Stage::vertex ? same->vertex : same->fragment, text.str()) << name;
  }
  EXPECT_GT(checked, 20);
}

TEST(VulkanGlsl, IsMarkedAsNotForTheNativeGlPathWithWhatAndWhere) {
  auto program = compile_glsl(
      "#version 450\n"
      "layout(location = 0) in vec3 position;\n"
      "layout(set = 0, binding = 0) uniform Transforms { mat4 mvp; };\n"
      "void main() { gl_Position = mvp * vec4(position, 1.0); }\n",
      "#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n");
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_NE(program->native_glsl_skip_reason.find("layout(set) at line 3"), std::string::npos)
      << program->native_glsl_skip_reason;
  EXPECT_EQ(vulkan_only_construct("layout(push_constant) uniform P { float x; } p;"), "layout(push_constant) at line 1");
  EXPECT_EQ(vulkan_only_construct("void main() { int i = gl_VertexIndex; }"), "gl_VertexIndex at line 1");
  EXPECT_EQ(vulkan_only_construct("layout(binding = 0) uniform sampler2D t;"), std::nullopt);
}

}  // namespace
}  // namespace shaderbed
