// What `shaderbed init` guesses a uniform or vertex input is: every name family, effect
// semantics, the book's registers, types (a mat3 normal matrix), mul() order, spaces, and
// names it must leave to the user (a TODO with a placeholder of the right size).
#include <gtest/gtest.h>

#include "author/BindingGuess.h"
#include "author/ShaderText.h"

namespace shaderbed {
namespace {

UniformFacts mat4(std::string name) { return {.name = std::move(name), .vecsize = 4, .columns = 4}; }
UniformFacts mat3(std::string name) { return {.name = std::move(name), .vecsize = 3, .columns = 3}; }
UniformFacts vec(std::string name, uint32_t n) { return {.name = std::move(name), .vecsize = n}; }

// The binding as one string: "transform", "diffuse,1", "0,0,0", plus "/row" for row_vector.
std::string bound(const UniformGuess& g) {
  std::string s;
  for (const BindingSource& b : g.sources) {
    if (!s.empty()) s += ",";
    if (!b.name.empty()) s += b.name;
    for (size_t i = 0; i < b.literal.size(); ++i) s += (i ? "," : "") + std::to_string(int(b.literal[i]));
  }
  if (g.layout == MatrixLayout::row_vector) s += "/row";
  return s;
}

std::string guess(const UniformFacts& u, Language language = Language::glsl, bool world_matrix = false) {
  return bound(guess_uniform(u, {.language = language, .has_world_matrix = world_matrix}));
}

TEST(BindingGuess, NameWordsDropPrefixesAndSplitGluedWords) {
  EXPECT_EQ(name_words("mWVP"), (std::vector<std::string>{"wvp"}));
  EXPECT_EQ(name_words("g_mWorldViewProjection"), (std::vector<std::string>{"world", "view", "projection"}));
  EXPECT_EQ(name_words("u_normal_matrix"), (std::vector<std::string>{"normal", "matrix"}));
  EXPECT_EQ(name_words("modelviewproj"), (std::vector<std::string>{"model", "view", "proj"}));
  EXPECT_EQ(name_words("g_fSpecularPower"), (std::vector<std::string>{"specular", "power"}));
}

TEST(BindingGuess, TransformFamily) {
  for (const char* name : {"WorldViewProj", "mWVP", "u_mvp", "ModelViewProjection", "modelViewProj", "uMVP",
                           "g_mWorldViewProjection", "Transform", "u_ModelViewProjectionMatrix"})
    EXPECT_EQ(guess(mat4(name)), "transform") << name;
}

TEST(BindingGuess, WorldViewProjectionAndTheirForms) {
  for (const char* name : {"World", "model", "u_model", "g_mWorld", "worldMatrix", "modelMatrix"})
    EXPECT_EQ(guess(mat4(name)), "world") << name;
  EXPECT_EQ(guess(mat4("view")), "view");
  EXPECT_EQ(guess(mat4("viewMatrix")), "view");
  for (const char* name : {"projection", "proj", "u_projection", "projectionMatrix", "ProjMatrix"})
    EXPECT_EQ(guess(mat4(name)), "projection") << name;
  EXPECT_EQ(guess(mat4("modelView")), "world_view");
  EXPECT_EQ(guess(mat4("u_mv")), "world_view");
  EXPECT_EQ(guess(mat4("viewProj")), "view_projection");
  EXPECT_EQ(guess(mat4("WorldInverseTranspose")), "world_inverse_transpose");
  EXPECT_EQ(guess(mat4("worldIT")), "world_inverse_transpose");
  EXPECT_EQ(guess(mat4("ViewInverse")), "view_inverse");
}

TEST(BindingGuess, NormalMatrixByType) {
  EXPECT_EQ(guess(mat3("normalMatrix")), "normal_matrix");
  EXPECT_EQ(guess(mat3("u_normal_matrix")), "normal_matrix");
  EXPECT_EQ(guess(mat4("normalMatrix")), "world_inverse_transpose");
  EXPECT_EQ(guess(vec("normalMatrix", 3)), "") << "a vector named so is not a matrix";
}

TEST(BindingGuess, EffectSemantics) {
  UniformFacts wvp = mat4("g_mFoo");
  wvp.semantic = "WORLDVIEWPROJECTION";
  EXPECT_EQ(guess(wvp, Language::hlsl), "transform");
  UniformFacts world = mat4("g_mBar");
  world.semantic = "WORLD";
  EXPECT_EQ(guess(world, Language::hlsl), "world");
  UniformFacts eye = vec("g_Something", 3);
  eye.semantic = "CAMERAPOSITION";
  EXPECT_EQ(guess(eye, Language::hlsl), "eye_position");
  UniformFacts power{.name = "g_fP", .semantic = "SPECULARPOWER"};
  EXPECT_EQ(guess(power, Language::hlsl), "power");
}

TEST(BindingGuess, RowVectorMatricesFromTheMulOrder) {
  UniformFacts row = mat4("WorldViewProj");
  row.mul_order = MatrixLayout::row_vector;
  EXPECT_EQ(guess(row, Language::hlsl), "transform/row");
  const UniformGuess g = guess_uniform(row, {.language = Language::hlsl});
  EXPECT_NE(g.reason.find("mul(v, WorldViewProj)"), std::string::npos) << g.reason;
  UniformFacts unseen = mat4("WorldViewProj");
  const UniformGuess assumed = guess_uniform(unseen, {.language = Language::hlsl});
  EXPECT_EQ(bound(assumed), "transform");
  EXPECT_NE(assumed.reason.find("column vectors are assumed"), std::string::npos) << assumed.reason;
}

TEST(BindingGuess, MulOrderFromTheSource) {
  const char* text = "float4 p = mul(v, WorldViewProj);\n"
                     "float3 n = mul(normal, (float3x3)g_mWorld);\n"
                     "float4 q = mul(Transform, float4(v.xyz, 1));\n";
  EXPECT_EQ(mul_order(text, "WorldViewProj"), MatrixLayout::row_vector);
  EXPECT_EQ(mul_order(text, "g_mWorld"), MatrixLayout::row_vector);
  EXPECT_EQ(mul_order(text, "Transform"), MatrixLayout::column_vector);
  EXPECT_EQ(mul_order(text, "Other"), std::nullopt);
}

TEST(BindingGuess, LightingVectorsAndTheirSpaces) {
  for (const char* name : {"lightDir", "LightDirection", "g_vLightDir", "u_light_dir", "LightVector"})
    EXPECT_EQ(guess(vec(name, 3), Language::hlsl), "light_vector") << name;
  EXPECT_EQ(guess(vec("lightPos", 3)), "light_position");
  EXPECT_EQ(guess(vec("lightPosition", 4)), "light_position");
  for (const char* name : {"eyePos", "camPosition", "viewPos", "EyePosition", "u_camera_position"})
    EXPECT_EQ(guess(vec(name, 3)), "eye_position") << name;
  // A shader with a world matrix lights in world space; names and declarations say so too.
  EXPECT_EQ(guess(vec("lightPos", 3), Language::glsl, true), "light_position_world");
  EXPECT_EQ(guess(vec("viewPos", 3), Language::glsl, true), "eye_position_world");
  EXPECT_EQ(guess(vec("worldLightDir", 3)), "light_vector_world");
  EXPECT_EQ(guess(vec("eyeSpaceLightPos", 3)), "light_position_view");
  UniformFacts declared = vec("g_LightDir", 3);
  declared.declared_space = SpaceHint::world;
  EXPECT_EQ(guess(declared, Language::hlsl), "light_vector_world");
  EXPECT_EQ(guess(vec("gl_LightSource[0].position", 4)), "light_position_view") << "GL keeps lights in eye space";
}

TEST(BindingGuess, DeclarationFactsFromTheSource) {
  const char* text = "float3 g_LightDir : DIRECTION\n<\n    string Space = \"World\";\n> = { 0, 1, 0 };\n"
                     "float3 g_EyePosition : CAMERAPOSITION;                  // world space\n"
                     "float3 LightVector   : register(c4);   // object space, unit\n"
                     "matrix Transform : register(c0);\n";
  EXPECT_EQ(declared_semantic(text, "g_LightDir"), "DIRECTION");
  EXPECT_EQ(declared_semantic(text, "LightVector"), "");
  EXPECT_EQ(declared_space(text, "g_LightDir"), SpaceHint::world);
  EXPECT_EQ(declared_space(text, "g_EyePosition"), SpaceHint::world);
  EXPECT_EQ(declared_space(text, "LightVector"), SpaceHint::object);
  EXPECT_EQ(declared_register(text, "LightVector"), 4);
  EXPECT_EQ(declared_register(text, "Transform"), 0);
  EXPECT_EQ(declared_register(text, "g_LightDir"), -1);
}

TEST(BindingGuess, BookRegistersWhenTheNameSaysNothing) {
  UniformFacts c0 = mat4("M0");
  c0.hlsl_register = 0;
  c0.mul_order = MatrixLayout::column_vector;
  EXPECT_EQ(guess(c0, Language::hlsl), "transform");
  UniformFacts c4 = vec("L", 3);
  c4.hlsl_register = 4;
  EXPECT_EQ(guess(c4, Language::hlsl), "light_vector");
  UniformFacts c5 = vec("E", 3);
  c5.hlsl_register = 5;
  EXPECT_EQ(guess(c5, Language::hlsl), "eye_position");
  UniformFacts c6 = vec("P", 3);
  c6.hlsl_register = 6;
  EXPECT_EQ(guess(c6, Language::hlsl), "light_position");
  UniformFacts c9 = vec("Q", 3);
  c9.hlsl_register = 9;
  EXPECT_TRUE(guess_uniform(c9, {.language = Language::hlsl}).todo());
}

TEST(BindingGuess, AmbientMaterialAndLightColours) {
  for (const char* name : {"ambientColor", "globalAmbient", "u_ambient", "AmbientLight", "gl_LightModel.ambient"})
    EXPECT_EQ(guess(vec(name, 3)), "ambient_light") << name;
  EXPECT_EQ(guess(vec("Ka", 3)), "1,1,1");
  EXPECT_EQ(guess(vec("gl_FrontMaterial.ambient", 4)), "1,1,1,1");
  EXPECT_EQ(guess(vec("Ke", 3)), "0,0,0");
  EXPECT_EQ(guess(vec("gl_FrontMaterial.emission", 4)), "0,0,0,1");
  for (const char* name : {"Kd", "objectColor", "MaterialDiffuse", "u_diffuse", "albedo", "diffuseColor"})
    EXPECT_EQ(guess(vec(name, 3)), "diffuse") << name;
  EXPECT_EQ(guess(vec("diffuseColor", 4)), "diffuse,1");
  EXPECT_EQ(guess(vec("gl_FrontMaterial.diffuse", 4)), "diffuse,1");
  for (const char* name : {"Ks", "specularColor", "g_MaterialSpecular"})
    EXPECT_EQ(guess(vec(name, 3)), "specular") << name;
  for (const char* name : {"shininess", "g_fSpecularPower", "specPower", "gl_FrontMaterial.shininess"})
    EXPECT_EQ(guess(UniformFacts{.name = name}), "power") << name;
  for (const char* name : {"lightColor", "LightColour", "gl_LightSource[0].diffuse"})
    EXPECT_EQ(guess(vec(name, 3)), "1,1,1") << name;
  EXPECT_EQ(guess(UniformFacts{.name = "padding"}), "0");
  const UniformGuess kd = guess_uniform(vec("Kd", 3), {});
  ASSERT_EQ(kd.parameters.size(), 1u);
  EXPECT_EQ(kd.parameters[0].name, "diffuse");
  EXPECT_EQ(kd.parameters[0].value.size(), 3u);
}

TEST(BindingGuess, LegacyMatricesAreTheScenes) {
  const UniformGuess g = guess_uniform(mat4("gl_ModelViewMatrix"), {});
  EXPECT_TRUE(g.bound_by_default);
  EXPECT_FALSE(g.todo());
  EXPECT_NE(g.reason.find("world_view"), std::string::npos) << g.reason;
}

TEST(BindingGuess, WhatItMustNotGuessIsATodoOfTheRightSize) {
  for (UniformFacts u : {UniformFacts{.name = "u_roughness"}, mat4("lightViewProj"), vec("u_time", 1), vec("fogColor", 3),
                         vec("u_params", 4)}) {
    const UniformGuess g = guess_uniform(u, {.language = Language::glsl});
    EXPECT_TRUE(g.todo()) << u.name << " guessed as " << bound(g);
    EXPECT_EQ(g.placeholder.size(), size_t(u.vecsize) * u.columns) << u.name;
  }
  const UniformGuess r = guess_uniform(UniformFacts{.name = "u_roughness"}, {.language = Language::glsl});
  EXPECT_EQ(r.reason, "bind 'u_roughness' (float): a case parameter, a scene quantity or a literal");
}

TEST(BindingGuess, VertexInputsByName) {
  const auto attribute = [](const char* name) {
    auto a = guess_attribute(name);
    return a ? a->attribute : std::string("-");
  };
  for (const char* name : {"aPos", "inPosition", "a_position", "vertex", "in_pos", "position", "vertexPosition"})
    EXPECT_EQ(attribute(name), "position") << name;
  for (const char* name : {"aNormal", "inNormal", "a_normal", "vertexNormal"}) EXPECT_EQ(attribute(name), "normal") << name;
  for (const char* name : {"aTexCoord", "inUV", "a_texcoord", "aTexCoords", "uv"}) EXPECT_EQ(attribute(name), "texcoord") << name;
  EXPECT_EQ(attribute("aTangent"), "tangent");
  EXPECT_EQ(attribute("aColor"), "color");
  EXPECT_EQ(attribute("aPackedThing"), "-");
  EXPECT_EQ(attribute("aPackedNormal"), "-") << "a packed normal travels in another stream";
  EXPECT_EQ(attribute("gl_Vertex"), "-") << "the legacy dialect places its own inputs";
}

TEST(BindingGuess, EntryPointsByTheirOutputs) {
  const char* text = "struct VOut { float4 p : POSITION; float3 n : TEXCOORD0; };\n"
                     "float helper(float x) { return x; }\n"
                     "VOut MyVertex(float4 p : POSITION) { VOut o; o.p = p; o.n = 0; return o; }\n"
                     "float4 MyPixel(VOut i) : COLOR0 { return 1; }\n"
                     "void CgStyle(float4 p : POSITION, out float4 oPos : POSITION) { oPos = p; }\n";
  auto found = entry_candidates(text, "x.hlsl");
  ASSERT_TRUE(found) << found.error().to_string();
  ASSERT_EQ(found->size(), 3u);
  EXPECT_EQ((*found)[0].function, "MyVertex");
  EXPECT_EQ((*found)[0].stage, Stage::vertex);
  EXPECT_EQ((*found)[1].function, "MyPixel");
  EXPECT_EQ((*found)[1].stage, Stage::fragment);
  EXPECT_EQ((*found)[2].function, "CgStyle");
  EXPECT_EQ((*found)[2].stage, Stage::vertex);
  EXPECT_EQ(glsl_stage_of("void main() { gl_Position = vec4(0); }"), Stage::vertex);
  EXPECT_EQ(glsl_stage_of("out vec4 c; void main() { c = vec4(1); }"), Stage::fragment);
}

}  // namespace
}  // namespace shaderbed

namespace shaderbed {
namespace {

TEST(BindingGuess, ComponentMeaningsFromTheDeclarationsComment) {
  const std::string text = "float4 SpecularColor;   // rgb = specular colour, w = specular power\nfloat4 Tint; // xyz: tint; a: opacity\n";
  EXPECT_EQ(component_meanings(text, "SpecularColor"),
            (std::vector<std::pair<std::string, std::string>>{{"rgb", "specular colour"}, {"w", "specular power"}}));
  EXPECT_EQ(component_meanings(text, "Tint"), (std::vector<std::pair<std::string, std::string>>{{"xyz", "tint"}, {"a", "opacity"}}));
}

TEST(BindingGuess, UnsureGuessesCarryTheirAlternative) {
  UniformFacts spec{.name = "SpecularColor", .vecsize = 4};
  const UniformGuess bare = guess_uniform(spec, {.language = Language::hlsl});
  EXPECT_TRUE(bare.unsure()) << "w = 1 without a comment is a doubt";
  ASSERT_EQ(bare.alternatives.size(), 1u);
  EXPECT_EQ(bare.alternatives[0].sources[1].name, "power");
  spec.component_meanings = {{"w", "specular power"}};
  const UniformGuess said = guess_uniform(spec, {.language = Language::hlsl});
  EXPECT_FALSE(said.unsure());
  EXPECT_EQ(said.sources[1].name, "power");

  UniformFacts matrix{.name = "g_World", .vecsize = 4, .columns = 4};
  const UniformGuess columns = guess_uniform(matrix, {.language = Language::hlsl});
  EXPECT_EQ(columns.doubt_group, "matrices");
  EXPECT_EQ(columns.alternatives.at(0).layout, MatrixLayout::row_vector);
  matrix.mul_order = MatrixLayout::column_vector;
  EXPECT_FALSE(guess_uniform(matrix, {.language = Language::hlsl}).unsure()) << "a mul() settles it";

  const UniformGuess light = guess_uniform({.name = "g_LightPos", .vecsize = 4}, {.language = Language::hlsl});
  EXPECT_TRUE(light.unsure());
  EXPECT_EQ(light.alternatives.at(0).sources.at(0).name, "light_vector");
  EXPECT_FALSE(guess_uniform({.name = "lightPos", .vecsize = 3}, {.language = Language::glsl}).unsure())
      << "a float3 position has no w to doubt";
}

TEST(BindingGuess, UnityNamesAndScaleFactors) {
  const UniformGuess unity = guess_uniform({.name = "_WorldSpaceLightPos0", .vecsize = 4}, {.language = Language::hlsl});
  EXPECT_EQ(unity.sources.at(0).name, "light_vector_world");
  EXPECT_EQ(guess_uniform({.name = "unity_ObjectToWorld", .vecsize = 4, .columns = 4}, {}).sources.at(0).name, "world");
  EXPECT_EQ(guess_uniform({.name = "unity_WorldToObject", .vecsize = 4, .columns = 4}, {}).sources.at(0).name, "world_inverse");
  EXPECT_EQ(guess_uniform({.name = "UNITY_MATRIX_MVP", .vecsize = 4, .columns = 4}, {}).sources.at(0).name, "transform");
  const UniformGuess debug = guess_uniform({.name = "u_ScaleFGDSpec", .vecsize = 3}, {.language = Language::glsl});
  ASSERT_EQ(debug.sources.size(), 1u);
  EXPECT_EQ(debug.sources[0].literal, (std::vector<double>{1.0, 1.0, 1.0}));
  EXPECT_EQ(guess_uniform({.name = "_Color", .vecsize = 4}, {}).sources.at(0).name, "diffuse");
}

}  // namespace
}  // namespace shaderbed
