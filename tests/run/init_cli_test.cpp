// `shaderbed init` through the binary: on each real-world-style shader of tests/realworld
// (copied into a private folder with what it includes and samples) it writes a case that
// loads and runs, with the obvious uniforms guessed exactly; what it cannot guess is a
// TODO listed after the run; a port given after its original joins the same variant; an
// existing case is never overwritten without --force; bad input is exit 2 with one line.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;

namespace fs = std::filesystem;
using shaderbed::test::TempDir;

// Copies tests/realworld/<name> into the folder, keeping its relative path.
void copy_realworld(const TempDir& dir, const std::string& name) {
  const fs::path to = dir.path() / name;
  fs::create_directories(to.parent_path());
  fs::copy_file(fs::path(SHADERBED_SOURCE_DIR) / "tests/realworld" / name, to, fs::copy_options::overwrite_existing);
}

// The case has a line that is exactly `code`, up to its trailing comment.
::testing::AssertionResult has_binding(const std::string& text, const std::string& code) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with(code) && (line.size() == code.size() || line[code.size()] == ' ')) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no line '" << code << "' in:\n" << text;
}

// Runs init (small images, no timing repeats needed: init draws once) and checks that every
// cell of the new case ran and passed.
std::string init_and_run(const TempDir& dir, const std::string& shaders, const std::string& case_name) {
  const auto [status, out] = shaderbed_cli("init " + shaders + " --size 32");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("wrote "), std::string::npos) << out;
  EXPECT_NE(out.find(" 0 failed, 0 known, 0 errors"), std::string::npos) << "every cell ran and passed:\n" << out;
  const std::string text = read_text(dir / case_name);
  EXPECT_TRUE(has_binding(text, "# Case written by `shaderbed init` from")) << text;
  EXPECT_EQ(text.find("TODO"), std::string::npos) << text;
  return text;
}

TEST(InitCli, DirectX9Effect) {
  TempDir dir("init_fx");
  copy_realworld(dir, "fx/blinn_phong.fx");
  const std::string c = init_and_run(dir, dir / "fx/blinn_phong.fx", "fx/blinn_phong.toml");
  EXPECT_TRUE(has_binding(c, R"(reference = { language = "hlsl", backend = "vulkan", path = "spirv" })"));
  EXPECT_TRUE(has_binding(c, R"(hlsl = { vertex = "blinn_phong.fx", fragment = "blinn_phong.fx", technique = "RenderSceneBlinnPhong", pass = "P0" })"));
  EXPECT_TRUE(has_binding(c, R"(g_mWorld = { value = "world", layout = "row_vector" })"));
  EXPECT_TRUE(has_binding(c, R"(g_mWorldViewProjection = { value = "transform", layout = "row_vector" })"));
  EXPECT_TRUE(has_binding(c, R"(g_LightDir = "light_vector_world")"));
  EXPECT_TRUE(has_binding(c, R"(g_EyePosition = "eye_position_world")"));
  EXPECT_TRUE(has_binding(c, R"(g_MaterialDiffuse = "diffuse")"));
  EXPECT_TRUE(has_binding(c, R"(g_fSpecularPower = "power")"));
  EXPECT_TRUE(has_binding(c, "power = 12.0"));
}

TEST(InitCli, GlslWithLegacyBuiltIns) {
  TempDir dir("init_glsl110");
  copy_realworld(dir, "glsl110/blinn_phong.vert");
  copy_realworld(dir, "glsl110/blinn_phong.frag");
  const std::string c = init_and_run(dir, dir / "glsl110/blinn_phong.vert" + " " + dir / "glsl110/blinn_phong.frag",
                                     "glsl110/blinn_phong.toml");
  EXPECT_TRUE(has_binding(c, R"(glsl = { vertex = "blinn_phong.vert", fragment = "blinn_phong.frag" })"));
  EXPECT_TRUE(has_binding(c, R"("gl_LightSource[0].position" = "light_position_view")"));
  EXPECT_TRUE(has_binding(c, R"("gl_LightSource[0].diffuse" = [1.0, 1.0, 1.0, 1.0])"));
  EXPECT_TRUE(has_binding(c, R"("gl_FrontMaterial.diffuse" = ["diffuse", 1.0])"));
  EXPECT_TRUE(has_binding(c, R"("gl_FrontMaterial.shininess" = "power")"));
  EXPECT_TRUE(has_binding(c, R"("gl_LightModel.ambient" = "ambient_light")"));
  EXPECT_TRUE(has_binding(c, "ambient = [0.1, 0.1, 0.1]"));
  EXPECT_TRUE(has_binding(c, "# gl_NormalMatrix")) << "the scene's matrices stay the defaults";
}

TEST(InitCli, Glsl330WithLooseUniforms) {
  TempDir dir("init_glsl330");
  copy_realworld(dir, "glsl330/blinn_phong.vert");
  copy_realworld(dir, "glsl330/blinn_phong.frag");
  const std::string c = init_and_run(dir, dir / "glsl330/blinn_phong.vert" + " " + dir / "glsl330/blinn_phong.frag",
                                     "glsl330/blinn_phong.toml");
  EXPECT_TRUE(has_binding(c, R"(model = "world")"));
  EXPECT_TRUE(has_binding(c, R"(view = "view")"));
  EXPECT_TRUE(has_binding(c, R"(projection = "projection")"));
  EXPECT_TRUE(has_binding(c, R"(normalMatrix = "normal_matrix")"));
  EXPECT_TRUE(has_binding(c, R"(lightPos = "light_position_world")"));
  EXPECT_TRUE(has_binding(c, R"(viewPos = "eye_position_world")"));
  EXPECT_TRUE(has_binding(c, R"(lightColor = [1.0, 1.0, 1.0])"));
  EXPECT_TRUE(has_binding(c, R"(ambientColor = "ambient_light")"));
  EXPECT_TRUE(has_binding(c, R"(objectColor = "diffuse")"));
  EXPECT_TRUE(has_binding(c, R"(aPos = "position")"));
  EXPECT_TRUE(has_binding(c, R"(aNormal = "normal")"));
}

TEST(InitCli, HlslSm5WithCbuffersAndATexture) {
  TempDir dir("init_hlsl5");
  copy_realworld(dir, "hlsl5/textured_diffuse.hlsl");
  copy_realworld(dir, "hlsl5/tan_constant.png");
  const std::string c = init_and_run(dir, dir / "hlsl5/textured_diffuse.hlsl", "hlsl5/textured_diffuse.toml");
  EXPECT_TRUE(has_binding(c, R"(hlsl = { vertex = "textured_diffuse.hlsl", fragment = "textured_diffuse.hlsl", vertex_entry = "TexturedDiffuseVS", fragment_entry = "TexturedDiffusePS" })"));
  EXPECT_TRUE(has_binding(c, R"(worldMatrix = { value = "world", layout = "row_vector" })"));
  EXPECT_TRUE(has_binding(c, R"(viewMatrix = { value = "view", layout = "row_vector" })"));
  EXPECT_TRUE(has_binding(c, R"(projectionMatrix = { value = "projection", layout = "row_vector" })"));
  EXPECT_TRUE(has_binding(c, R"(diffuseColor = ["diffuse", 1.0])"));
  EXPECT_NE(c.find("# padding                                   # declared but never read by the compiled shader"),
            std::string::npos) << c;   // a cbuffer's padding needs no binding
  EXPECT_TRUE(has_binding(c, R"(shaderTexture = { file = "tan_constant.png" })"));
  EXPECT_TRUE(has_binding(c, R"(SampleType = { filter = "linear", address = "wrap" })"));
}

TEST(InitCli, CgLibraryWithEntriesInTwoFiles) {
  TempDir dir("init_cg");
  for (const char* f : {"cg/basic_light_v.cg", "cg/basic_light_f.cg", "cg/light_library.cgh"}) copy_realworld(dir, f);
  const std::string c = init_and_run(dir, dir / "cg/basic_light_v.cg" + " " + dir / "cg/basic_light_f.cg",
                                     "cg/basic_light_v.toml");
  EXPECT_TRUE(has_binding(c, R"(cg = { vertex = "basic_light_v.cg", fragment = "basic_light_f.cg", vertex_entry = "basicLight_v", fragment_entry = "basicLight_f" })"));
  EXPECT_TRUE(has_binding(c, R"(modelViewProj = "transform")"));
  EXPECT_TRUE(has_binding(c, R"(lightPosition = "light_position")"));
  EXPECT_TRUE(has_binding(c, R"(eyePosition = "eye_position")"));
  EXPECT_TRUE(has_binding(c, R"(globalAmbient = "ambient_light")"));
  EXPECT_TRUE(has_binding(c, "Ke = [0.0, 0.0, 0.0]"));
  EXPECT_TRUE(has_binding(c, "Ka = [1.0, 1.0, 1.0]"));
  EXPECT_TRUE(has_binding(c, R"(Kd = "diffuse")"));
  EXPECT_TRUE(has_binding(c, R"(shininess = "power")"));
}

TEST(InitCli, HlslWithTwoNamedEntries) {
  TempDir dir("init_hlsl");
  copy_realworld(dir, "hlsl/lambert_two_entries.hlsl");
  const std::string c = init_and_run(dir, dir / "hlsl/lambert_two_entries.hlsl", "hlsl/lambert_two_entries.toml");
  EXPECT_TRUE(has_binding(c, R"(hlsl = { vertex = "lambert_two_entries.hlsl", fragment = "lambert_two_entries.hlsl", vertex_entry = "LightVertexShader", fragment_entry = "LightPixelShader" })"));
  EXPECT_TRUE(has_binding(c, R"(WorldViewProj = "transform")")) << "mul(WorldViewProj, v): column vectors";
  EXPECT_TRUE(has_binding(c, R"(LightDir = "light_vector")"));
  EXPECT_TRUE(has_binding(c, R"(MaterialDiffuse = "diffuse")"));
}

// The original first, its port after: one variant, the original the reference.
TEST(InitCli, OriginalAndPortShareTheVariant) {
  TempDir dir("init_port");
  copy_realworld(dir, "hlsl/lambert_two_entries.hlsl");
  dir.write("port.vert", "#version 330 core\nlayout(location = 0) in vec3 aPos;\nlayout(location = 1) in vec3 aNormal;\n"
                         "uniform mat4 u_mvp;\nout vec3 vNormal;\n"
                         "void main() { gl_Position = u_mvp * vec4(aPos, 1.0); vNormal = aNormal; }\n");
  dir.write("port.frag", "#version 330 core\nin vec3 vNormal;\nuniform vec3 u_lightDir;\nuniform vec3 u_diffuse;\n"
                         "out vec4 fragColor;\n"
                         "void main() { fragColor = vec4(u_diffuse * clamp(dot(normalize(vNormal), u_lightDir), 0.0, 1.0), 1.0); }\n");
  const std::string c = init_and_run(dir, dir / "hlsl/lambert_two_entries.hlsl" + " " + dir / "port.vert" + " " + dir / "port.frag",
                                     "hlsl/lambert_two_entries.toml");
  EXPECT_TRUE(has_binding(c, R"(reference = { language = "hlsl", backend = "vulkan", path = "spirv" })"));
  EXPECT_TRUE(has_binding(c, R"(glsl = { vertex = "../port.vert", fragment = "../port.frag" })"));
  EXPECT_TRUE(has_binding(c, R"(u_mvp = "transform")"));
  EXPECT_TRUE(has_binding(c, R"(u_lightDir = "light_vector")"));
  EXPECT_TRUE(has_binding(c, R"(u_diffuse = "diffuse")"));
}

// What it cannot guess: a commented-out binding with a TODO, so the case loads; the run
// says the uniform is unbound, and both are listed under "still needs you".
TEST(InitCli, UnguessableUniformIsATodoAndTheRunSaysItIsUnbound) {
  TempDir dir("init_todo");
  dir.write("rough.vert", "#version 330 core\nlayout(location = 0) in vec3 aPos;\nuniform mat4 u_mvp;\n"
                          "void main() { gl_Position = u_mvp * vec4(aPos, 1.0); }\n");
  dir.write("rough.frag", "#version 330 core\nuniform float u_roughness;\nout vec4 fragColor;\n"
                          "void main() { fragColor = vec4(vec3(u_roughness), 1.0); }\n");
  const auto [status, out] = shaderbed_cli("init " + dir / "rough.vert" + " " + dir / "rough.frag" + " --size 32");
  EXPECT_EQ(status, 1) << out;
  const std::string c = read_text(dir / "rough.toml");
  EXPECT_TRUE(has_binding(c, "# u_roughness = 0.0")) << c;
  EXPECT_NE(c.find("TODO: bind 'u_roughness' (float): a case parameter, a scene quantity or a literal"), std::string::npos) << c;
  EXPECT_TRUE(has_binding(c, R"(u_mvp = "transform")"));
  EXPECT_NE(out.find("still needs you"), std::string::npos) << out;
  EXPECT_NE(out.find("TODO line"), std::string::npos) << out;
  EXPECT_NE(out.find("'u_roughness'"), std::string::npos) << out;
  EXPECT_NE(out.find("has no binding"), std::string::npos) << "the run's error names the unbound uniform:\n" << out;
}

TEST(InitCli, NeverOverwritesWithoutForce) {
  TempDir dir("init_force");
  copy_realworld(dir, "hlsl/lambert_two_entries.hlsl");
  const std::string shader = dir / "hlsl/lambert_two_entries.hlsl";
  const std::string case_path = dir / "mine.toml";
  auto [first, out1] = shaderbed_cli("init " + shader + " --out " + case_path + " --no-run");
  ASSERT_EQ(first, 0) << out1;
  const std::string edited = read_text(case_path) + "# my own edit\n";
  dir.write("mine.toml", edited);
  auto [again, out2] = shaderbed_cli("init " + shader + " --out " + case_path + " --no-run");
  EXPECT_EQ(again, 2) << out2;
  EXPECT_NE(out2.find("--force"), std::string::npos) << out2;
  EXPECT_EQ(read_text(case_path), edited) << "the file is unchanged";
  auto [forced, out3] = shaderbed_cli("init " + shader + " --out " + case_path + " --no-run --force");
  EXPECT_EQ(forced, 0) << out3;
  EXPECT_EQ(read_text(case_path).find("# my own edit"), std::string::npos) << "--force rewrites it";
  // The case resolves its shader from its own folder.
  EXPECT_TRUE(has_binding(read_text(case_path), R"(hlsl = { vertex = "hlsl/lambert_two_entries.hlsl", fragment = "hlsl/lambert_two_entries.hlsl", vertex_entry = "LightVertexShader", fragment_entry = "LightPixelShader" })"));
}

TEST(InitCli, BadInputIsOneLineAndExitTwo) {
  TempDir dir("init_bad");
  dir.write("notes.txt", "not a shader\n");
  dir.write("helper.hlsl", "float4 Brighten(float4 c) { return c * 2; }\n");
  dir.write("only.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
  const std::pair<std::string, std::string> cases[] = {
      {dir / "missing.hlsl", "no such shader file"},
      {dir / "notes.txt", "unknown shader extension '.txt'"},
      {dir / "helper.hlsl", "no vertex entry point found"},
      {dir / "only.vert", "GLSL needs a vertex and a fragment shader"},
      {dir / "only.vert --lang fortran", "--lang"}};
  for (const auto& [args, message] : cases) {
    const auto [status, out] = shaderbed_cli("init " + args + " --no-run");
    EXPECT_EQ(status, 2) << args << ":\n" << out;
    EXPECT_NE(out.find(message), std::string::npos) << args << ":\n" << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << "one line:\n" << out;
  }
  EXPECT_FALSE(fs::exists(dir / "helper.toml"));
}

}  // namespace

namespace {

// Issue 26 §6's effect and WebGL shaders: init writes a case that runs, shaders unedited.
TEST(InitCli, EffectWithAD3D10BranchThatIsOff) {
  TempDir dir("init_fx_sm4");
  copy_realworld(dir, "fx/lambert_sm4_fallback.fx");
  init_and_run(dir, dir / "fx/lambert_sm4_fallback.fx", "fx/lambert_sm4_fallback.toml");
}

TEST(InitCli, EffectWithATextureVariableAndInitialValues) {
  TempDir dir("init_fx_textured");
  copy_realworld(dir, "fx/textured_blinn_phong.fx");
  copy_realworld(dir, "fx/tan_constant.png");
  init_and_run(dir, dir / "fx/textured_blinn_phong.fx", "fx/textured_blinn_phong.toml");
}

TEST(InitCli, UnversionedWebGl1) {
  TempDir dir("init_webgl1");
  copy_realworld(dir, "webgl/lambert.vert");
  copy_realworld(dir, "webgl/lambert.frag");
  init_and_run(dir, dir / "webgl/lambert.vert" + " " + dir / "webgl/lambert.frag", "webgl/lambert.toml");
}

TEST(InitCli, WebGl2Es300) {
  TempDir dir("init_webgl2");
  copy_realworld(dir, "webgl/blinn_phong.vert");
  copy_realworld(dir, "webgl/blinn_phong.frag");
  init_and_run(dir, dir / "webgl/blinn_phong.vert" + " " + dir / "webgl/blinn_phong.frag", "webgl/blinn_phong.toml");
}

}  // namespace
