#pragma once
// The legacy-GLSL dialect layer: GL-era GLSL (no #version, 110-140, or a compatibility
// profile) rewritten into a #version 450 shader that glslang compiles for SPIR-V, with
// every line of the author's file where it was (a #line marker follows the dialect's
// declarations), so glslang's messages point at the author's lines.
//
//   attribute / varying           -> in / out (vertex), in (fragment)
//   gl_Vertex, gl_Normal, gl_Color, gl_MultiTexCoord0
//                                 -> vertex inputs named so in the reflection
//   gl_ModelViewMatrix, gl_ProjectionMatrix, gl_ModelViewProjectionMatrix (and their
//   Inverse, Transpose, InverseTranspose forms), gl_NormalMatrix
//                                 -> uniforms (scene matrices by default, below)
//   ftransform()                  -> gl_ModelViewProjectionMatrix * gl_Vertex
//   gl_LightSource[n].member, gl_FrontMaterial.member, gl_LightModel.ambient
//                                 -> one uniform each, reflected as
//                                    "gl_LightSource[0].diffuse", "gl_FrontMaterial.shininess"
//   gl_FrontLightProduct[n].*, gl_FrontLightModelProduct.sceneColor, spotCosCutoff
//                                 -> expressions of those uniforms, as Mesa computes them
//                                    (rgb products, the material's alpha)
//   gl_FrontColor (vertex) / gl_Color (fragment), gl_TexCoord[]
//                                 -> varyings
//   gl_FragColor, gl_FragData[0]  -> the output at location 0
//   texture2D, texture2DProj, texture2DLod, textureCube, ... -> texture, textureProj, ...
// In GLSL 1.10/1.20 an author's identifier that is a keyword of 4.50 (texture, sample,
// flat, smooth, layout, ...) is renamed and reflected under the author's name.
//
// Unsupported built-ins (gl_BackMaterial, gl_SecondaryColor, fog, gl_ClipVertex,
// halfVector (it assumes GL's eye looking down -z), shadow lookups, a non-literal light
// index, ...) are one error naming the built-in and its line.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "compile/Compiler.h"
#include "compile/GlslProfile.h"
#include "core/Error.h"

namespace shaderbed {

struct LegacyGlslTranslation {
  std::string text;                                 // the #version 450 source
  std::map<std::string, std::string> legacy_names;  // dialect name -> the name reflected ("gl_Vertex")
};

Result<LegacyGlslTranslation> translate_legacy_glsl(const ShaderSource& source, const GlslVersion& version);

// The scene quantity (scene/Scene.h) a legacy matrix uniform takes when the case binds
// nothing to it: gl_ModelViewMatrix -> "world_view", gl_ProjectionMatrix ->
// "projection", gl_ModelViewProjectionMatrix -> "transform", gl_NormalMatrix ->
// "normal_matrix_view", "...Inverse" -> "..._inverse" and so on. Light and material
// state has no default: the case binds it.
std::optional<std::string> legacy_glsl_default_binding(std::string_view legacy_name);

}  // namespace shaderbed
