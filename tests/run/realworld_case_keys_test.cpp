// The front-end gaps public shaders hit (issue 26 §6), each on its own real-style shader in
// tests/realworld, through the runner with the shader files unchanged: a glTF-style PBR
// pair switched by the case's `defines` (per case and per variant), a Unity ShaderLab
// .shader whose CGPROGRAM block includes UnityCG.cginc from the case's `include_dirs`, a
// BINORMAL vertex stream, a bool uniform bound to a TOML boolean, HLSL in .vs/.ps and GLSL
// in .glsl/.vsh/.fsh, and uniforms and samplers that are declared but never read (no
// binding: a warning, not an error). Each model case also fails when its input is wrong.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "TempDir.h"
#include "compile/Compiler.h"
#include "run/Runner.h"
#include "scene/CaseFile.h"
#include "scene/CaseProgram.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

Result<RunReport> run_case_keys_case(const std::string& cases_dir, const std::string& name) {
  return run_suite(test::quick_run(cases_dir, name, 32));
}

class CaseKeysStyles : public ::testing::TestWithParam<std::string> {};

TEST_P(CaseKeysStyles, EveryCellPassesWithTheShadersAsWritten) {
  auto report = run_case_keys_case((kRealWorld / "cases").string(), GetParam());
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  const std::set<std::string> paths = test::paths_all_with_status(*report, "pass");
  EXPECT_TRUE(paths.contains("vulkan/spirv") && paths.contains("gl/spirv") && paths.contains("gl/cross"));
}

INSTANTIATE_TEST_SUITE_P(RealWorld, CaseKeysStyles,
                         ::testing::Values("gltf_pbr", "unity_lambert_tint", "hlsl_lambert_tangent_frame",
                                           "extensions_light_vs_ps", "extensions_lambert_glsl",
                                           "extensions_half_lambert"));

// Mesa's own GLSL compiler reads the defines too: the glTF case runs on gl/glsl.
TEST(CaseKeysDefines, NativeGlPathCompilesTheDefinedSource) {
  auto report = run_case_keys_case((kRealWorld / "cases").string(), "gltf_pbr");
  ASSERT_TRUE(report) << report.error().to_string();
  EXPECT_TRUE(test::paths_all_with_status(*report, "pass").contains("gl/glsl"));
}

// The defines decide what compiles: the case's HAS_NORMALS gives the normal input, the
// variant's own HAS_TANGENTS adds the tangent; without defines neither is an input.
TEST(CaseKeysDefines, CaseAndVariantDefinesReachTheCompiledShader) {
  auto c = load_case((kRealWorld / "cases" / "gltf_pbr.toml").string());
  ASSERT_TRUE(c) << c.error().to_string();
  const auto inputs_of = [&](const ShaderFiles& files) {
    std::set<std::string> names;
    auto source = load_case_program(Language::glsl, files, c->path);
    EXPECT_TRUE(source) << source.error().to_string();
    if (!source) return names;
    auto program = compile_program(*source, false);
    EXPECT_TRUE(program) << program.error().to_string();
    if (program)
      for (const StageInput& in : program->vertex.reflection.inputs) names.insert(in.name);
    return names;
  };
  const ShaderFiles& normals = c->variants[0].name == "normals" ? c->variants[0].shaders.at(Language::glsl)
                                                                : c->variants[1].shaders.at(Language::glsl);
  const ShaderFiles& tangents = c->variants[0].name == "normals" ? c->variants[1].shaders.at(Language::glsl)
                                                                 : c->variants[0].shaders.at(Language::glsl);
  EXPECT_EQ(inputs_of(normals), (std::set<std::string>{"a_Position", "a_Normal"}));
  EXPECT_EQ(inputs_of(tangents), (std::set<std::string>{"a_Position", "a_Normal", "a_Tangent"}));
  ShaderFiles bare = normals;
  bare.defines.clear();
  EXPECT_EQ(inputs_of(bare), (std::set<std::string>{"a_Position"}));
}

// Writes a case into a folder whose shader root is tests/realworld (through symlinks).
fs::path case_beside_corpus(const test::TempDir& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir.path() / "cases");
  for (const char* folder : {"unity", "extensions", "hlsl", "gltf"})
    if (!fs::exists(dir.path() / folder)) fs::create_directory_symlink(kRealWorld / folder, dir.path() / folder);
  std::ofstream(dir.path() / "cases" / (name + ".toml")) << text;
  return dir.path() / "cases";
}

std::string read_corpus_case(const std::string& name) {
  std::ifstream in(kRealWorld / "cases" / (name + ".toml"));
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The bool reaches the shader: `halfLambert = true` draws half-Lambert, which the Lambert model fails.
TEST(CaseKeysBoolUniform, TrueSelectsTheOtherBranchAndFails) {
  test::TempDir dir("case_keys_bool");
  const std::string text = replaced(read_corpus_case("extensions_half_lambert"), "\nhalfLambert = false", "\nhalfLambert = true");
  auto report = run_case_keys_case(case_beside_corpus(dir, "half_lambert_true", text).string(), "half_lambert_true");
  ASSERT_TRUE(report) << report.error().to_string();
  test::paths_all_with_status(*report, "fail");
}

// Without include_dirs the ShaderLab file's #include "UnityCG.cginc" is an error at its line in the .shader file.
TEST(CaseKeysIncludeDirs, WithoutTheFolderTheIncludeIsAnErrorAtItsLine) {
  test::TempDir dir("case_keys_include");
  const std::string text = replaced(read_corpus_case("unity_lambert_tint"), "include_dirs = [\"unity/CGIncludes\"]", "");
  auto report = run_case_keys_case(case_beside_corpus(dir, "no_include_dirs", text).string(), "no_include_dirs");
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(to_string(r.status), "error") << r.id();
    EXPECT_NE(r.message.find("LambertTint.shader:18"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("UnityCG.cginc"), std::string::npos) << r.message;
  }
}

// The binormal stream is normal x tangent: bound as the tangent instead, T x T is zero and the render fails.
TEST(CaseKeysBinormal, TheTangentInItsPlaceFails) {
  test::TempDir dir("case_keys_binormal");
  const std::string text = read_corpus_case("hlsl_lambert_tangent_frame") + "\n[attributes.hlsl]\n\"Input.Binormal\" = \"tangent\"\n";
  auto report = run_case_keys_case(case_beside_corpus(dir, "binormal_as_tangent", text).string(), "binormal_as_tangent");
  ASSERT_TRUE(report) << report.error().to_string();
  for (const CellResult& r : report->results) EXPECT_NE(to_string(r.status), "pass") << r.id();
}

// Declared, never read, unbound: each is a warning on every cell, by name.
TEST(CaseKeysUnread, UnreadUniformsAndSamplersAreWarnings) {
  auto report = run_case_keys_case((kRealWorld / "cases").string(), "extensions_lambert_glsl");
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    std::string all;
    for (const std::string& w : r.warnings) all += w + "\n";
    EXPECT_NE(all.find("uniform 'uTime' has no binding"), std::string::npos) << r.id() << ": " << all;
    EXPECT_NE(all.find("sampler 'uShadowMap' has no binding"), std::string::npos) << r.id() << ": " << all;
  }
}

// A uniform the shader reads still needs its binding: an error, as before.
TEST(CaseKeysUnread, AReadUniformWithoutBindingIsStillAnError) {
  test::TempDir dir("case_keys_read");
  const std::string text = replaced(read_corpus_case("extensions_lambert_glsl"), "uDiffuse = \"diffuse\"", "");
  auto report = run_case_keys_case(case_beside_corpus(dir, "missing_diffuse", text).string(), "missing_diffuse");
  ASSERT_TRUE(report) << report.error().to_string();
  for (const CellResult& r : report->results) {
    EXPECT_EQ(to_string(r.status), "error") << r.id();
    EXPECT_NE(r.message.find("uDiffuse"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
