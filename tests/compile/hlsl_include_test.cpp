// HLSL #include (compile/HlslIncluder.h) on real glslang: headers are found relative to
// the including file (also when nested in another folder), `#pragma once` is honoured, a
// missing header is one error naming it at the including line, and every file read is
// reported so the disk compile cache keys it.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "compile/Compiler.h"

namespace shaderbed {
namespace {

using test::TempDir;

const std::string kPixel =
    "#include \"lib/lighting.hlsli\"\n"
    "float3 LightDir;\n"
    "float4 main(float3 n : TEXCOORD0) : COLOR0 { return float4(lambert(normalize(n), LightDir).xxx, 1); }\n";

Result<ShaderModule> compile_file(const std::string& path, std::vector<SourceFile>* read = nullptr) {
  auto source = load_shader_source(Stage::fragment, path);
  if (!source) return std::unexpected(source.error());
  return compile_stage(Language::hlsl, *source, Target::vulkan, read);
}

TEST(HlslInclude, FoundRelativeToTheIncludingFileAndReported) {
  TempDir dir("hlsl_include");
  const std::string header = dir.write("shaders/lib/lighting.hlsli",
                                       "float lambert(float3 n, float3 l) { return saturate(dot(n, l)); }\n");
  const std::string main = dir.write("shaders/light_ps.hlsl", kPixel);
  std::vector<SourceFile> read;
  auto module = compile_file(main, &read);
  ASSERT_TRUE(module) << module.error().to_string();
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].path, header);
  EXPECT_EQ(read[0].text, "float lambert(float3 n, float3 l) { return saturate(dot(n, l)); }\n");
}

TEST(HlslInclude, NestedIncludesResolveFromEachIncludingFile) {
  TempDir dir("hlsl_include");
  // lib/lighting.hlsli includes "terms/diffuse.hlsli", i.e. lib/terms/diffuse.hlsli, which
  // includes "../common.hlsli" twice (once guarded by #pragma once).
  dir.write("shaders/lib/common.hlsli", "#pragma once\nstatic const float kOne = 1.0;\n");
  dir.write("shaders/lib/terms/diffuse.hlsli",
            "#include \"../common.hlsli\"\n#include \"../common.hlsli\"\n"
            "float diffuse(float3 n, float3 l) { return kOne * saturate(dot(n, l)); }\n");
  dir.write("shaders/lib/lighting.hlsli",
            "#include \"terms/diffuse.hlsli\"\nfloat lambert(float3 n, float3 l) { return diffuse(n, l); }\n");
  std::vector<SourceFile> read;
  auto module = compile_file(dir.write("shaders/light_ps.hlsl", kPixel), &read);
  ASSERT_TRUE(module) << module.error().to_string();
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read[0].path, dir / "shaders/lib/lighting.hlsli");
  EXPECT_EQ(read[1].path, dir / "shaders/lib/terms/diffuse.hlsli");
  EXPECT_EQ(read[2].path, dir / "shaders/lib/common.hlsli");
}

TEST(HlslInclude, AMissingHeaderIsAnErrorNamingItAtTheIncludingLine) {
  TempDir dir("hlsl_include");
  const std::string main = dir.write("shaders/light_ps.hlsl", "float3 LightDir;\n" + kPixel);
  auto module = compile_file(main);
  ASSERT_FALSE(module);
  EXPECT_EQ(module.error().file, main);
  EXPECT_EQ(module.error().line, 2);
  EXPECT_NE(module.error().message.find("lib/lighting.hlsli"), std::string::npos) << module.error().to_string();
}

TEST(HlslInclude, AnErrorInsideAHeaderNamesTheHeaderAndItsLine) {
  TempDir dir("hlsl_include");
  const std::string header =
      dir.write("shaders/lib/lighting.hlsli", "\n\nfloat lambert(float3 n, float3 l) { return saturate(dot(n, q)); }\n");
  auto module = compile_file(dir.write("shaders/light_ps.hlsl", kPixel));
  ASSERT_FALSE(module);
  EXPECT_EQ(module.error().file, header);
  EXPECT_EQ(module.error().line, 3);
}

TEST(HlslInclude, AnEffectFileIncludesItsHeadersToo) {
  TempDir dir("hlsl_include");
  dir.write("fx/common.fxh", "float4x4 WorldViewProj;\nfloat4 Colour;\n");
  const std::string effect = dir.write(
      "fx/flat.fx",
      "#include \"common.fxh\"\n"
      "float4 VS(float4 p : POSITION) : POSITION { return mul(WorldViewProj, p); }\n"
      "float4 PS() : COLOR0 { return Colour; }\n"
      "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
  auto vs = load_shader_source(Stage::vertex, effect);
  auto fs = load_shader_source(Stage::fragment, effect);
  ASSERT_TRUE(vs && fs);
  auto program = compile_program(ProgramSource{.language = Language::hlsl, .vertex = *vs, .fragment = *fs}, false);
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_EQ(program->vertex.entry_point, "VS");
  EXPECT_EQ(program->fragment.entry_point, "PS");
}

}  // namespace
}  // namespace shaderbed
