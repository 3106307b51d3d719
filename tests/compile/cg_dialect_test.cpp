// The Cg dialect layer (harness/compile/CgDialect.h) on real glslang: every Cg shader of
// the library compiles, Cg's types, semantics, uniform parameters and #include work,
// and every unsupported Cg construct is one named error at its file and line.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ReflectionLookup.h"
#include "SourceTree.h"
#include "TempDir.h"
#include "compile/CgDialect.h"
#include "compile/Compiler.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

using test::find_member;

const fs::path kCgShaders = test::kShaders / "cg";

ShaderSource cg_source(Stage stage, std::string text, std::string path = "test.cg") {
  return ShaderSource{.stage = stage, .path = std::move(path), .text = std::move(text)};
}

Result<ShaderModule> compile_cg(Stage stage, std::string text, std::string path = "test.cg",
                                Target target = Target::vulkan) {
  return compile_stage(Language::cg, cg_source(stage, std::move(text), std::move(path)), target);
}

using test::TempDir;

// The location of the stage variable whose SPIR-V name is `name` (from the disassembly).
int location_of(const std::vector<uint32_t>& spirv, const std::string& name) {
  const std::string text = disassemble(spirv);
  const std::string key = "OpDecorate %" + name + " Location ";
  const auto at = text.find(key);
  if (at == std::string::npos) return -1;
  return std::stoi(text.substr(at + key.size()));
}

// ---- the library ---------------------------------------------------------------

TEST(CgDialect, EveryLibraryCgShaderCompilesForBothTargets) {
  int compiled = 0;
  for (const auto& entry : fs::directory_iterator(kCgShaders)) {
    if (entry.path().extension() != ".cg") continue;  // .cgh are included, not compiled alone
    const std::string name = entry.path().stem().string();
    const Stage stage = name.ends_with("_fp") ? Stage::fragment : Stage::vertex;
    ASSERT_TRUE(name.ends_with("_fp") || name.ends_with("_vp")) << name << ": Cg programs are named *_vp/*_fp";
    auto src = load_shader_source(stage, entry.path().string());
    ASSERT_TRUE(src) << src.error().to_string();
    for (Target target : {Target::vulkan, Target::opengl}) {
      auto m = compile_stage(Language::cg, *src, target);
      ASSERT_TRUE(m) << m.error().to_string();
      EXPECT_FALSE(m->spirv.empty());
      ++compiled;
    }
  }
  EXPECT_GE(compiled, 2 * 31);
}

TEST(CgDialect, LibraryProgramsLinkAsPrograms) {
  ProgramSource p{Language::cg, *load_shader_source(Stage::vertex, (kCgShaders / "setup_vp.cg").string()),
                  *load_shader_source(Stage::fragment, (kCgShaders / "oren_nayar_lut_fp.cg").string())};
  auto program = compile_program(p);
  ASSERT_TRUE(program) << program.error().to_string();
  // The LUT sampler is a uniform parameter of main: it must get its own binding, not the
  // $Global block's.
  ASSERT_EQ(program->fragment.reflection.samplers.size(), 1u);
  ASSERT_EQ(program->fragment.reflection.uniform_blocks.size(), 1u);
  EXPECT_EQ(program->fragment.reflection.samplers[0].name, "angleTex");
  EXPECT_NE(program->fragment.reflection.samplers[0].binding, program->fragment.reflection.uniform_blocks[0].binding);
  EXPECT_NE(program->fragment_gl.reflection.samplers[0].binding,
            program->vertex_gl.reflection.uniform_blocks[0].binding);
}

// ---- uniform parameters, types, semantics ----------------------------------------

TEST(CgDialect, UniformParametersBecomeUniformMembersWithTheirCgNames) {
  auto src = load_shader_source(Stage::vertex, (kCgShaders / "phong_vp.cg").string());
  ASSERT_TRUE(src);
  auto m = compile_stage(Language::cg, *src, Target::vulkan);
  ASSERT_TRUE(m) << m.error().to_string();
  for (const char* name : {"modelViewProj", "lightDir", "eyePosition", "Kd", "Ks", "shininess"})
    EXPECT_NE(find_member(m->reflection, name), nullptr) << name;
  const UniformMember* mvp = find_member(m->reflection, "modelViewProj");
  ASSERT_NE(mvp, nullptr);
  EXPECT_EQ(mvp->offset, 0u);
  EXPECT_EQ(mvp->columns, 4u);
  EXPECT_TRUE(mvp->column_registers) << "mul(modelViewProj, position): a column per register, as HLSL";
  const UniformMember* kd = find_member(m->reflection, "Kd");
  ASSERT_NE(kd, nullptr);
  EXPECT_TRUE(kd->is_float);
  EXPECT_EQ(kd->vecsize, 3u) << "half3 is a float3";
  ASSERT_EQ(m->reflection.inputs.size(), 2u);
  EXPECT_EQ(m->reflection.inputs[0].semantic, "SV_POSITION");
  EXPECT_EQ(m->reflection.inputs[1].semantic, "NORMAL");
}

TEST(CgDialect, HalfAndFixedCompileAsFloat) {
  auto m = compile_cg(Stage::fragment,
                      "half4 main(half3 c : COLOR0,\n"
                      "           uniform half4x4 h44, uniform fixed3 f3, uniform fixed2x2 f22, uniform half h1,\n"
                      "           uniform fixed f1, uniform half1 h11) : COLOR\n"
                      "{\n"
                      "    fixed4 a = fixed4(c * f3, 0.5x) * 1.0h;\n"
                      "    half2 b = mul(f22, half2(h1, f1)) + h11.x;\n"
                      "    return mul(h44, a) + b.xyxy;\n"
                      "}\n");
  ASSERT_TRUE(m) << m.error().to_string();
  const UniformMember* h44 = find_member(m->reflection, "h44");
  const UniformMember* f3 = find_member(m->reflection, "f3");
  const UniformMember* f22 = find_member(m->reflection, "f22");
  ASSERT_TRUE(h44 && f3 && f22);
  EXPECT_EQ(h44->columns, 4u);
  EXPECT_EQ(h44->vecsize, 4u);
  EXPECT_EQ(f3->vecsize, 3u);
  EXPECT_EQ(f22->columns, 2u);
  EXPECT_TRUE(h44->is_float && f3->is_float && f22->is_float);
}

TEST(CgDialect, VaryingsLinkByCgSemanticNotByOrder) {
  // The fragment program reads only TEXCOORD2 and COLOR1; under Cg they meet the vertex
  // program's TEXCOORD2 and COLOR1 whatever else either side declares.
  auto vs = compile_cg(Stage::vertex,
                       "void main(float4 p : POSITION, out float4 oP : POSITION, out float3 a : TEXCOORD0,\n"
                       "          out float3 b : TEXCOORD2, out float4 c0 : COLOR0, out float4 c1 : COL1)\n"
                       "{ oP = p; a = p.xyz; b = p.zyx; c0 = p; c1 = p.wzyx; }\n");
  auto fs = compile_cg(Stage::fragment,
                       "float4 main(float4 col : COLOR1, float3 t : TEX2) : COLOR { return col + t.xyzz; }\n");
  ASSERT_TRUE(vs) << vs.error().to_string();
  ASSERT_TRUE(fs) << fs.error().to_string();
  EXPECT_EQ(location_of(vs->spirv, "a"), 0);
  EXPECT_EQ(location_of(vs->spirv, "b"), 2);
  EXPECT_EQ(location_of(vs->spirv, "c0"), cg_varying_location("COLOR0"));
  EXPECT_EQ(location_of(vs->spirv, "c1"), cg_varying_location("COLOR1"));
  EXPECT_EQ(location_of(fs->spirv, "t"), 2);
  EXPECT_EQ(location_of(fs->spirv, "col"), cg_varying_location("COLOR1"));
}

TEST(CgDialect, ReturnStructsAndStructInputsWork) {
  auto vs = compile_cg(Stage::vertex,
                       "struct a2v { float4 position : POSITION; float3 normal : NORMAL; };\n"
                       "struct v2f { float4 position : POSITION; half3 color : COLOR0; float3 n : TEXCOORD3; };\n"
                       "v2f main(a2v IN, uniform float4x4 modelViewProj, uniform half3 Kd)\n"
                       "{\n"
                       "    v2f OUT;\n"
                       "    OUT.position = mul(modelViewProj, IN.position);\n"
                       "    OUT.color = Kd;\n"
                       "    OUT.n = IN.normal;\n"
                       "    return OUT;\n"
                       "}\n");
  ASSERT_TRUE(vs) << vs.error().to_string();
  EXPECT_NE(find_member(vs->reflection, "modelViewProj"), nullptr);
  EXPECT_NE(disassemble(vs->spirv).find("Location 3"), std::string::npos);
}

TEST(CgDialect, VaryingWithANonCgSemanticIsAnErrorAtItsLine) {
  auto m = compile_cg(Stage::vertex,
                      "void main(float4 p : POSITION,\n"
                      "          out float4 oP : POSITION,\n"
                      "          out float3 oN : NORMAL)\n"
                      "{ oP = p; oN = p.xyz; }\n",
                      "varying.cg");
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, "varying.cg");
  EXPECT_EQ(m.error().line, 3);
  EXPECT_NE(m.error().message.find("NORMAL"), std::string::npos) << m.error().message;
}

TEST(CgDialect, VaryingWithoutASemanticIsAnErrorAtTheEntry) {
  auto m = compile_cg(Stage::fragment,
                      "// no semantic on n\n"
                      "float4 main(float3 n) : COLOR { return n.xyzz; }\n",
                      "nosemantic.cg");
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, "nosemantic.cg");
  EXPECT_EQ(m.error().line, 2);
  EXPECT_NE(m.error().message.find("no semantic"), std::string::npos) << m.error().message;
}

TEST(CgDialect, OverlappingVaryingsAreAnError) {
  auto m = compile_cg(Stage::vertex,
                      "void main(float4 p : POSITION, out float4 oP : POSITION,\n"
                      "          out float4x4 m : TEXCOORD0, out float4 t : TEXCOORD2)\n"
                      "{ oP = p; m = float4x4(p, p, p, p); t = p; }\n");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("overlaps"), std::string::npos) << m.error().message;
}

TEST(CgDialect, CgOnlySemanticsMapToBuiltins) {
  // WPOS is the fragment coordinate; FACE is Cg's +1/-1 from the front-facing flag.
  auto m = compile_cg(Stage::fragment,
                      "float4 main(float4 wpos : WPOS, float face : FACE, float3 n : TEXCOORD1) : COLOR\n"
                      "{\n"
                      "    return float4(n * face, 1) + wpos * 0.001;\n"
                      "}\n");
  ASSERT_TRUE(m) << m.error().to_string();
  const std::string text = disassemble(m->spirv);
  EXPECT_NE(text.find("BuiltIn FragCoord"), std::string::npos);
  EXPECT_NE(text.find("BuiltIn FrontFacing"), std::string::npos);
  auto gl = compile_cg(Stage::fragment, "half4 main(float face : FACE) : COLOR { return face; }\n", "face.cg",
                       Target::opengl);
  ASSERT_TRUE(gl) << gl.error().to_string();
}

TEST(CgDialect, AttrSemanticsFollowNvidiaAliasing) {
  auto m = compile_cg(Stage::vertex,
                      "void main(float4 p : ATTR0, float3 n : ATTR2, float3 t : ATTR14, out float4 oP : HPOS,\n"
                      "          out float3 oN : TEXCOORD0, uniform float4x4 modelViewProj)\n"
                      "{ oP = mul(modelViewProj, p); oN = n + t; }\n");
  ASSERT_TRUE(m) << m.error().to_string();
  ASSERT_EQ(m->reflection.inputs.size(), 3u);
  EXPECT_EQ(m->reflection.inputs[0].semantic, "SV_POSITION");
  EXPECT_EQ(m->reflection.inputs[1].semantic, "NORMAL");
  EXPECT_EQ(m->reflection.inputs[2].semantic, "TANGENT");
}

TEST(CgDialect, SamplerParametersGetTheirOwnBindings) {
  auto m = compile_cg(Stage::fragment,
                      "float4 main(float3 n : TEXCOORD1,\n"
                      "            uniform sampler2D angleTex,\n"
                      "            uniform float3 Kd,\n"
                      "            uniform sampler3D wardTex : TEXUNIT3) : COLOR\n"
                      "{\n"
                      "    return tex2D(angleTex, n.xy) * tex3D(wardTex, n) * float4(Kd, 1);\n"
                      "}\n");
  ASSERT_TRUE(m) << m.error().to_string();
  ASSERT_EQ(m->reflection.samplers.size(), 2u);
  ASSERT_EQ(m->reflection.uniform_blocks.size(), 1u);
  const uint32_t ubo = m->reflection.uniform_blocks[0].binding;
  const uint32_t a = m->reflection.samplers[0].binding, b = m->reflection.samplers[1].binding;
  EXPECT_NE(a, b);
  EXPECT_NE(a, ubo);
  EXPECT_NE(b, ubo);
  for (const SamplerBinding& s : m->reflection.samplers)
    if (s.name == "wardTex") {
      EXPECT_EQ(s.dimensions, 3u);
    }
  EXPECT_NE(find_member(m->reflection, "Kd"), nullptr);
}

TEST(CgDialect, LitRaisesToThePower) {
  // glslang 12's own lit() multiplies instead of raising to the power.
  auto m = compile_cg(Stage::fragment,
                      "float4 main(float2 d : TEXCOORD0, uniform float shininess) : COLOR\n"
                      "{ return lit(d.x, d.y, shininess); }\n");
  ASSERT_TRUE(m) << m.error().to_string();
  EXPECT_NE(disassemble(m->spirv).find("Pow"), std::string::npos);
}

TEST(CgDialect, ProfilePragmasAreDroppedWithAReason) {
  auto prepared = prepare_cg_file(
      "#pragma profileoption NumTemps=8\n"
      "#pragma bind main.Kd = C3\n"
      "#pragma pack_matrix(row_major)\n"
      "float x = 0.5x;\n",
      "p.cg");
  ASSERT_TRUE(prepared);
  ASSERT_EQ(prepared->notes.size(), 2u);
  EXPECT_EQ(prepared->notes[0].line, 1);
  EXPECT_NE(prepared->notes[0].text.find("profileoption"), std::string::npos);
  EXPECT_EQ(prepared->notes[1].line, 2);
  EXPECT_NE(prepared->text.find("#pragma pack_matrix"), std::string::npos) << "glslang applies pack_matrix";
  EXPECT_EQ(prepared->text, "\n\n#pragma pack_matrix(row_major)\nfloat x = 0.5;\n");
  auto m = compile_cg(Stage::fragment,
                      "#pragma profileoption NumTemps=8\n"
                      "#pragma option O3\n"
                      "float4 main(float4 c : COLOR0) : COLOR { return c; }\n");
  ASSERT_TRUE(m) << m.error().to_string();
}

// ---- errors ------------------------------------------------------------------------

TEST(CgDialect, CgErrorCarriesFileAndLine) {
  auto m = compile_cg(Stage::fragment,
                      "// a broken fragment program\n"
                      "half4 main(half3 c : COLOR0,\n"
                      "           uniform half3 Kd) : COLOR\n"
                      "{\n"
                      "    return half4(c * Kd +, 1);\n"
                      "}\n",
                      "broken_fp.cg");
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, "broken_fp.cg");
  EXPECT_EQ(m.error().line, 5);
  EXPECT_EQ(m.error().stage, ErrorStage::compile);
}

struct UnsupportedCase {
  const char* construct;  // as the error names it
  Stage stage;
  const char* body;  // line 3 of the program holds the construct
};

// Each program puts its unsupported construct on line 3.
const UnsupportedCase kUnsupported[] = {
    {"texRECT", Stage::fragment,
     "static const float texRECTangle = 1;   // an identifier, not texRECT\n"
     "float4 main(float2 uv : TEXCOORD0, uniform sampler2D t) : COLOR {\n"
     "  return texRECT(t, uv) * texRECTangle;\n}\n"},
    {"samplerRECT", Stage::fragment,
     "// rectangle\n\nfloat4 main(float2 uv : TEXCOORD0, uniform samplerRECT r) : COLOR\n{ return 0; }\n"},
    {"tex2Dproj", Stage::fragment,
     "float4 main(float3 uv : TEXCOORD0,\n uniform sampler2D t) : COLOR {\n  return tex2Dproj(t, uv);\n}\n"},
    {"tex1Dproj", Stage::fragment,
     "float4 main(float2 uv : TEXCOORD0,\n uniform sampler1D t) : COLOR {\n  return tex1Dproj(t, uv);\n}\n"},
    {"texCUBEproj", Stage::fragment,
     "float4 main(float4 uv : TEXCOORD0,\n uniform samplerCUBE t) : COLOR {\n  return texCUBEproj(t, uv);\n}\n"},
    {"samplerBUF", Stage::fragment, "\n\nuniform samplerBUF b;\nfloat4 main() : COLOR { return 0; }\n"},
    {"f4tex2D", Stage::fragment,
     "float4 main(float2 uv : TEXCOORD0,\n uniform sampler2D t) : COLOR {\n  return f4tex2D(t, uv);\n}\n"},
    {"interface", Stage::fragment,
     "// a Cg interface\n\ninterface Light { float3 illuminate(float3 p); };\nfloat4 main() : COLOR { return 0; }\n"},
    {"packed", Stage::fragment, "\n\nuniform packed float4 a[4];\nfloat4 main() : COLOR { return a[0]; }\n"},
    {"unsized array parameter 'lights[]'", Stage::fragment,
     "float4 main(float3 n : TEXCOORD0,\n"
     "            uniform float3 Kd,\n"
     "            uniform float3 lights[]) : COLOR { return 0; }\n"},
    {"pack_4ubyte", Stage::fragment,
     "float4 main(float4 c : COLOR0) : COLOR {\n  float p = 0;\n  p = pack_4ubyte(c);\n  return p;\n}\n"},
    {"noise", Stage::fragment,
     "float4 main(float3 n : TEXCOORD0) : COLOR {\n  float noise = 1;\n  return noise(n) * noise;\n}\n"},
    {"semantic BCOL0", Stage::vertex,
     "void main(float4 p : POSITION, out float4 oP : POSITION,\n"
     "          out float4 front : COLOR0,\n"
     "          out float4 back : BCOL0) { oP = p; front = p; back = p; }\n"},
    {"semantic BCOL1", Stage::vertex,
     "void main(float4 p : POSITION, out float4 oP : POSITION,\n\n"
     "          out float4 back : BCOL1) { oP = p; back = p; }\n"},
    {"semantic FOG", Stage::vertex,
     "void main(float4 p : POSITION, out float4 oP : POSITION,\n\n"
     "          out float fog : FOG) { oP = p; fog = p.z; }\n"},
    {"semantic PSIZE", Stage::fragment,
     "float4 main(float3 n : TEXCOORD0,\n\n            float size : PSIZE) : COLOR { return size; }\n"},
    {"semantic CLP0", Stage::vertex,
     "void main(float4 p : POSITION, out float4 oP : POSITION,\n\n"
     "          out float clip : CLP0) { oP = p; clip = p.x; }\n"},
    {"semantic WPOS", Stage::vertex, "void main(float4 p : POSITION,\n\n          out float4 oP : WPOS) { oP = p; }\n"},
    {"semantic ATTR3", Stage::fragment, "float4 main(\n\n  float4 c : ATTR3) : COLOR { return c; }\n"},
    {"semantic FACE outside the entry parameters", Stage::fragment,
     "struct frag_in {\n  float3 n : TEXCOORD0;\n  float face : FACE;\n};\n"
     "float4 main(frag_in IN) : COLOR { return IN.face; }\n"},
    {"tex2D(sampler2D, float3)", Stage::fragment,
     "float4 main(float3 uvz : TEXCOORD0,\n             uniform sampler2D shadowMap) : COLOR {\n"
     "  return tex2D(shadowMap, uvz);\n}\n"},
};

TEST(CgDialect, EachUnsupportedConstructIsOneNamedErrorAtItsLine) {
  for (const UnsupportedCase& c : kUnsupported) {
    SCOPED_TRACE(c.construct);
    for (Target target : {Target::vulkan, Target::opengl}) {
      auto m = compile_cg(c.stage, c.body, "unsupported.cg", target);
      ASSERT_FALSE(m) << "compiled";
      const Error& e = m.error();
      EXPECT_EQ(e.file, "unsupported.cg");
      EXPECT_EQ(e.line, 3) << e.to_string();
      EXPECT_EQ(e.stage, ErrorStage::compile);
      EXPECT_NE(
          e.message.find(std::string("Cg feature '") + c.construct + "' is not supported by shaderbed's Cg layer"),
          std::string::npos)
          << e.message;
      EXPECT_EQ(e.message.find("more errors"), std::string::npos) << "one error, not a cascade: " << e.message;
    }
  }
}

TEST(CgDialect, DetectionIgnoresCommentsStringsAndOtherIdentifiers) {
  auto m = compile_cg(Stage::fragment,
                      "// texRECT and samplerRECT in a comment, interface too\n"
                      "/* packed noise(x) : FOG\n"
                      "   BCOL0 */\n"
                      "#if 0\n"
                      "float4 old(float2 uv : TEXCOORD0, uniform samplerRECT r) : COLOR { return texRECT(r, uv); }\n"
                      "#endif\n"
                      "#define MESSAGE \"texRECT\"\n"
                      "float texRECTangle(float FOG) { return FOG; }\n"
                      "float4 main(float3 n : TEXCOORD0, uniform float packedness) : COLOR\n"
                      "{\n"
                      "    float noise = texRECTangle(n.x);\n"
                      "    float FOG = n.y > 0 ? noise : packedness;\n"
                      "    switch (int(n.z)) { case 1: FOG = 2; break; default: break; }\n"
                      "    return float4(n.y > 0 ? FOG : noise, 0, 0, 1);\n"
                      "}\n");
  ASSERT_TRUE(m) << m.error().to_string();
}

TEST(CgDialect, ExplicitCoordinateConstructorIsNotADepthCompare) {
  auto m = compile_cg(Stage::fragment,
                      "float4 main(float3 uvz : TEXCOORD0, uniform sampler2D t) : COLOR\n"
                      "{ return tex2D(t, uvz.xy) + tex2D(t, float2(uvz.x, uvz.z)); }\n");
  ASSERT_TRUE(m) << m.error().to_string();
}

// ---- #include ----------------------------------------------------------------------

TEST(CgDialect, IncludeResolvesRelativeToTheIncludingFile) {
  TempDir dir;
  dir.write("lib/common.cgh",
            "// common\n"
            "#include \"more/deeper.cgh\"\n"
            "half3 tint(half3 c) { return c * twice(0.5); }\n");
  dir.write("lib/more/deeper.cgh", "#pragma once\nfloat twice(float x) { return 2.0 * x; }\n");
  dir.write("lib/again.cgh", "#include \"more/deeper.cgh\"\n");
  const std::string main = dir.write("prog_fp.cg",
                                     "#include \"lib/common.cgh\"\n"
                                     "#include \"lib/again.cgh\"\n"
                                     "half4 main(half3 c : COLOR0, uniform half3 Kd) : COLOR\n"
                                     "{ return half4(tint(c * Kd), 1); }\n");
  auto src = load_shader_source(Stage::fragment, main);
  ASSERT_TRUE(src);
  auto m = compile_stage(Language::cg, *src, Target::vulkan);
  ASSERT_TRUE(m) << m.error().to_string() << " (#pragma once must stop the second include of deeper.cgh)";
}

TEST(CgDialect, ErrorInsideAnIncludedFileNamesThatFileAndLine) {
  TempDir dir;
  const std::string header = dir.write("inc/broken.cgh",
                                       "// helpers\n"
                                       "float3 helper(float3 x)\n"
                                       "{\n"
                                       "    return x * ;\n"
                                       "}\n");
  const std::string main = dir.write("prog_fp.cg",
                                     "// program\n"
                                     "#include \"inc/broken.cgh\"\n"
                                     "float4 main(float3 n : TEXCOORD0) : COLOR { return float4(helper(n), 1); }\n");
  auto m = compile_stage(Language::cg, *load_shader_source(Stage::fragment, main), Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(fs::path(m.error().file), fs::path(header).lexically_normal());
  EXPECT_EQ(m.error().line, 4) << m.error().to_string();
}

TEST(CgDialect, UnsupportedConstructInsideAnIncludedFileNamesThatFileAndLine) {
  TempDir dir;
  const std::string header = dir.write("rect.cgh",
                                       "// rectangle helpers\n"
                                       "\n"
                                       "float4 lookup(samplerRECT r, float2 uv) { return texRECT(r, uv); }\n");
  const std::string main = dir.write("prog_fp.cg",
                                     "#include \"rect.cgh\"\n"
                                     "float4 main(float2 uv : TEXCOORD0) : COLOR { return uv.xyxy; }\n"
                                     "float4 after() { return 0; }\n");
  auto m = compile_stage(Language::cg, *load_shader_source(Stage::fragment, main), Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(fs::path(m.error().file), fs::path(header).lexically_normal());
  EXPECT_EQ(m.error().line, 3);
  EXPECT_NE(m.error().message.find("'samplerRECT'"), std::string::npos) << m.error().message;
}

TEST(CgDialect, LinesAfterAnIncludeStayTheAuthorsLines) {
  TempDir dir;
  dir.write("five_lines.cgh", "// 1\n// 2\nfloat one() { return 1; }\n// 4\n// 5\n");
  const std::string main = dir.write("prog_fp.cg",
                                     "#include \"five_lines.cgh\"\n"
                                     "float4 main(float2 uv : TEXCOORD0) : COLOR\n"
                                     "{\n"
                                     "    return undefined_name;\n"
                                     "}\n");
  auto m = compile_stage(Language::cg, *load_shader_source(Stage::fragment, main), Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, main);
  EXPECT_EQ(m.error().line, 4);
}

TEST(CgDialect, MissingIncludeIsAnErrorAtTheIncludeLine) {
  TempDir dir;
  const std::string main = dir.write("prog_fp.cg",
                                     "// program\n"
                                     "#include \"nowhere.cgh\"\n"
                                     "float4 main() : COLOR { return 0; }\n");
  auto m = compile_stage(Language::cg, *load_shader_source(Stage::fragment, main), Target::vulkan);
  ASSERT_FALSE(m);
  EXPECT_EQ(m.error().file, main);
  EXPECT_EQ(m.error().line, 2);
  EXPECT_NE(m.error().message.find("nowhere.cgh"), std::string::npos) << m.error().message;
}

}  // namespace
}  // namespace shaderbed
