// A leading UTF-8 byte order mark is dropped where a shader's text is read
// (compile/ShaderFileText.h), for the file a case names and each file it #includes, in
// every language (issue 30, item 15).
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "compile/Compiler.h"
#include "compile/ShaderFileText.h"

namespace shaderbed {
namespace {

constexpr const char* kBom = "\xEF\xBB\xBF";

TEST(ShaderBom, OnlyALeadingMarkIsDropped) {
  EXPECT_EQ(without_utf8_bom(std::string(kBom) + "float4 x;"), "float4 x;");
  EXPECT_EQ(without_utf8_bom("float4 x;"), "float4 x;");
  EXPECT_EQ(without_utf8_bom(std::string("a") + kBom), std::string("a") + kBom);
  EXPECT_EQ(without_utf8_bom("\xEF\xBB"), "\xEF\xBB");
}

TEST(ShaderBom, FilesAndIncludesWithAMarkCompileInEveryLanguage) {
  test::TempDir dir("shader_bom");
  dir.write("common.hlsli", std::string(kBom) + "float4 tint;\n");
  const std::string hlsl = dir.write(
      "p.hlsl", std::string(kBom) + "#include \"common.hlsli\"\nfloat4 main() : COLOR { return tint; }\n");
  const std::string glsl = dir.write("f.frag", std::string(kBom) +
                                                   "#version 450\nlayout(location = 0) out vec4 c;\n"
                                                   "void main() { c = vec4(1.0); }\n");
  const std::string cg = dir.write("p_fp.cg", std::string(kBom) + "float4 main() : COLOR { return float4(1, 0, 0, 1); }\n");
  for (const auto& [language, path] : {std::pair{Language::hlsl, hlsl}, std::pair{Language::glsl, glsl},
                                       std::pair{Language::cg, cg}}) {
    auto source = load_shader_source(Stage::fragment, path);
    ASSERT_TRUE(source) << source.error().to_string();
    EXPECT_FALSE(source->text.starts_with(kBom)) << path;
    auto module = compile_stage(language, *source, Target::vulkan);
    EXPECT_TRUE(module) << path << ": " << (module ? "" : module.error().to_string());
  }
}

}  // namespace
}  // namespace shaderbed
