// `shaderbed init` on original/port pairs written the way real shaders are
// (tests/author/init_pairs/), each a finding where init's guess once turned a correct port
// into a failing one: it binds both languages alike, checks its own guesses by running the
// case (switching what it was unsure of when the original draws nothing or the port
// disagrees, and saying what it changed), and gives no verdict against a port while a
// guess is unconfirmed. Real renders through the binary, 32 px.
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

namespace fs = std::filesystem;
using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;
using shaderbed::test::TempDir;

// A pair's folder copied into a private one, so the case init writes stays out of the tree.
void copy_pair(const TempDir& dir, const std::string& pair) {
  fs::copy(fs::path(SHADERBED_SOURCE_DIR) / "tests/author/init_pairs" / pair, dir.path(), fs::copy_options::recursive);
}

// `from` replaced by `to` in a copied shader: a variant of the pair for one test.
void edit(const TempDir& dir, const std::string& file, const std::string& from, const std::string& to) {
  std::string text = read_text(dir / file);
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  text.replace(at, from.size(), to);
  dir.write(file, text);
}

::testing::AssertionResult has_line(const std::string& text, const std::string& code) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with(code) && (line.size() == code.size() || line[code.size()] == ' ')) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no line '" << code << "' in:\n" << text;
}

struct Init {
  int status = -1;
  std::string out;
  std::string case_text;
};

Init init(const TempDir& dir, const std::string& files, const std::string& case_name) {
  std::string args;
  std::istringstream names(files);
  for (std::string f; names >> f;) args += " " + dir / f;
  auto [status, out] = shaderbed_cli("init" + args + " --size 32");
  return {status, out, read_text(dir / case_name)};
}

const char* const kAllPass = "28 cells: 28 passed, 0 failed, 0 known, 0 errors";

TEST(InitGuessCheck, SpecularColourWhoseCommentSaysWIsThePower) {
  TempDir dir("init_pair_specular");
  copy_pair(dir, "specular_w_power");
  const Init r = init(dir, "gloss.hlsl gloss.vert gloss.frag", "gloss.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(SpecularColor = ["specular", "power"])"));
  EXPECT_TRUE(has_line(r.case_text, R"(uShininess = "power")"));
  EXPECT_EQ(r.out.find("init's check changed"), std::string::npos) << "the comment settles it:\n" << r.out;
}

// Without the comment, w = 1 is a doubt: the port disagrees, and init's check switches w
// to the exponent and says so.
TEST(InitGuessCheck, SpecularColourWithoutACommentIsSwitchedByTheCheck) {
  TempDir dir("init_pair_specular_bare");
  copy_pair(dir, "specular_w_power");
  edit(dir, "gloss.hlsl", "// rgb = specular colour, w = specular power", "");
  const Init r = init(dir, "gloss.hlsl gloss.vert gloss.frag", "gloss.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("init's check changed 1 of its guesses"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("'SpecularColor' now bound as `SpecularColor = [\"specular\", \"power\"]` instead of w = 1"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(SpecularColor = ["specular", "power"])"));
  EXPECT_NE(r.case_text.find("init's check run switched to this"), std::string::npos) << r.case_text;
}

TEST(InitGuessCheck, PortSamplesAsTheOriginalsSamplerState) {
  TempDir dir("init_pair_sampler");
  copy_pair(dir, "sampler_wrap");
  const Init r = init(dir, "tiled.hlsl tiled.vert tiled.frag", "tiled.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(tileSampler = { filter = "linear", address = "wrap" })"));
  EXPECT_TRUE(has_line(r.case_text, R"(u_tiles = { file = "tiles.png", filter = "linear", address = "wrap" })"));
}

// No mul() names the effect's matrices (the technique passes them to the vertex shader):
// column vectors leave the original blank, so the check switches them to rows together.
TEST(InitGuessCheck, MatricesThroughCompileArgumentsAreSwitchedToRowVectors) {
  TempDir dir("init_pair_rows");
  copy_pair(dir, "compile_rows");
  const Init r = init(dir, "lit.fx lit.vert lit.frag", "lit.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("'g_WorldViewProj', 'g_World' now bound as"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("before, the original drew no valid reference (28 of 28 cells judged nothing); after, all 28 cells pass"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(g_WorldViewProj = { value = "transform", layout = "row_vector" })"));
  EXPECT_TRUE(has_line(r.case_text, R"(g_World = { value = "world", layout = "row_vector" })"));
  EXPECT_TRUE(has_line(r.case_text, R"(u_modelViewProjection = "transform")"));
}

TEST(InitGuessCheck, UnitysLightIsADirection) {
  TempDir dir("init_pair_unity");
  copy_pair(dir, "unity_light");
  const Init r = init(dir, "toon.hlsl toon.vert toon.frag", "toon.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(_WorldSpaceLightPos0 = "light_vector_world")"));
  EXPECT_TRUE(has_line(r.case_text, R"(u_lightDirWorld = "light_vector_world")"));
  EXPECT_TRUE(has_line(r.case_text, R"(UNITY_MATRIX_MVP = "transform")"));
  EXPECT_TRUE(has_line(r.case_text, R"(unity_ObjectToWorld = "world")"));
  EXPECT_TRUE(has_line(r.case_text, R"(_Color = ["diffuse", 1.0])"));
}

// A float4 "light position" the shader uses as a direction (w = 0): the port disagrees
// until the check switches it.
TEST(InitGuessCheck, LightPositionUsedAsADirectionIsSwitched) {
  TempDir dir("init_pair_light_w");
  copy_pair(dir, "unity_light");
  edit(dir, "toon.hlsl", "float4 _WorldSpaceLightPos0;", "float4 g_LightPos;");
  edit(dir, "toon.hlsl", "= _WorldSpaceLightPos0.xyz;", "= g_LightPos.xyz;");
  const Init r = init(dir, "toon.hlsl toon.vert toon.frag", "toon.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("'g_LightPos' now bound as `g_LightPos = \"light_vector_world\"` instead of a position (w = 1)"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(has_line(r.case_text, R"(g_LightPos = "light_vector_world")"));
}

TEST(InitGuessCheck, DebugFactorIsOneNotASpecularColour) {
  TempDir dir("init_pair_debug");
  copy_pair(dir, "debug_scale");
  const Init r = init(dir, "brdf.vert brdf.frag brdf_port.hlsl", "brdf.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(kAllPass), std::string::npos) << r.out;
  EXPECT_TRUE(has_line(r.case_text, "u_ScaleFGDSpec = [1.0, 1.0, 1.0]"));
  EXPECT_TRUE(has_line(r.case_text, R"(u_SpecularColor = "specular")"));
  EXPECT_TRUE(has_line(r.case_text, R"(g_SpecularColor = "specular")"));
}

// A port that is really wrong, with an original whose light init could not settle: no
// switch makes the port agree, so init gives no verdict against the port and lists the
// binding to check first, with its line.
TEST(InitGuessCheck, NoVerdictAgainstThePortWhileAGuessIsUnconfirmed) {
  TempDir dir("init_pair_unconfirmed");
  copy_pair(dir, "unity_light");
  edit(dir, "toon.hlsl", "float4 _WorldSpaceLightPos0;", "float4 g_LightPos;");
  edit(dir, "toon.hlsl", "= _WorldSpaceLightPos0.xyz;", "= g_LightPos.xyz;");
  edit(dir, "toon.frag", "u_color.rgb * ndotl", "u_color.rgb * ndotl * ndotl");
  const Init r = init(dir, "toon.hlsl toon.vert toon.frag", "toon.toml");
  EXPECT_EQ(r.status, 1) << r.out;
  // The line the case binds it on.
  int line = 0;
  std::istringstream lines(r.case_text);
  for (std::string text; std::getline(lines, text) && !text.starts_with("g_LightPos = ");) ++line;
  EXPECT_NE(r.out.find("check these bindings first:\n    line " + std::to_string(line + 1) + ": 'g_LightPos': "), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("the port's source computes something else"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no verdict on the port until the bindings above are checked"), std::string::npos) << r.out;
}

// Every guess settled by the shaders' text: a port that disagrees gets the run's verdict.
TEST(InitGuessCheck, VerdictStandsWhenNoGuessIsInDoubt) {
  TempDir dir("init_pair_verdict");
  copy_pair(dir, "specular_w_power");
  edit(dir, "gloss.frag", "uSpecularColor * specular", "uSpecularColor * specular * 2.0");
  const Init r = init(dir, "gloss.hlsl gloss.vert gloss.frag", "gloss.toml");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(r.out.find("check these bindings first"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("glsl: 16 cells failed (port: "), std::string::npos) << r.out;
}

// The real-world corpus's front-end styles (tests/realworld/extensions): a bool switch is
// guessed off, not a TODO, and a uniform or sampler the compiled shader never reads needs
// no binding, so init ends with nothing for the user to fill in.
void copy_realworld(const TempDir& dir, const std::string& folder) {
  fs::copy(fs::path(SHADERBED_SOURCE_DIR) / "tests/realworld" / folder, dir.path(), fs::copy_options::recursive);
}

TEST(InitGuessCheck, ABoolSwitchIsGuessedOffNotLeftAsATodo) {
  TempDir dir("init_bool_switch");
  copy_realworld(dir, "extensions");
  const Init r = init(dir, "half_lambert.vsh half_lambert.fsh", "half_lambert.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(has_line(r.case_text, "halfLambert = 0.0"));
  EXPECT_EQ(r.case_text.find("TODO"), std::string::npos) << r.case_text;
  EXPECT_NE(r.out.find("16 cells: 16 passed"), std::string::npos) << r.out;
}

TEST(InitGuessCheck, WhatTheShaderNeverReadsNeedsNoBinding) {
  TempDir dir("init_unread");
  copy_realworld(dir, "extensions");
  const Init r = init(dir, "lambert_vertex.glsl lambert_fragment.glsl", "lambert_vertex.toml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(r.case_text.find("TODO"), std::string::npos) << r.case_text;
  EXPECT_NE(r.case_text.find("# uTime"), std::string::npos) << r.case_text;
  EXPECT_NE(r.case_text.find("never sampled by the compiled shader"), std::string::npos) << r.case_text;
}

}  // namespace
