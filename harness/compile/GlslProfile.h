#pragma once
// What kind of GLSL a source is, from a cheap token scan (no preprocessing): its
// #version and profile, whether it needs the legacy dialect (GL-era built-ins), whether
// it declares loose uniforms (glslang's relaxed Vulkan rules), and whether it uses
// Vulkan-only GLSL that the native GL path cannot take.
#include <optional>
#include <string>
#include <string_view>

namespace shaderbed {

struct GlslVersion {
  int number = 110;            // no #version: GLSL 1.10
  bool declared = false;
  bool es = false;
  bool compatibility = false;  // "#version NNN compatibility"
  int line = 0;                // of the #version directive; 0 = none
};

GlslVersion glsl_version(std::string_view text);

// WebGL 1's GLSL as browsers take it: no #version (so GLSL ES 1.00), told from desktop
// GLSL 1.10 by a default precision statement (`precision mediump float;`), which 1.10
// cannot parse and an ES 1.00 fragment shader must have.
bool is_unversioned_glsl_es(const GlslVersion& version, std::string_view text);

// GLSL ES of any form: `#version 100`, `#version 300 es` and up, or unversioned WebGL 1.
bool is_glsl_es(const GlslVersion& version, std::string_view text);

// Whether the text asks for reduced precision: a `mediump` or `lowp` anywhere (a default
// precision statement or a qualifier). Only ES shaders mean it; desktop GLSL ignores them.
bool declares_reduced_precision(std::string_view text);

// Desktop GLSL of the GL-era: no #version, 110-140, or a compatibility profile. Mesa
// compiles it only in a compatibility context; glslang only through the dialect.
bool is_legacy_glsl(const GlslVersion& version);

// A uniform outside a block that is not opaque (`uniform mat4 model;`), or gl_VertexID
// / gl_InstanceID: what glslang's relaxed Vulkan rules are for.
bool needs_relaxed_vulkan_rules(std::string_view text);

// The first Vulkan-only construct (layout(set/push_constant/input_attachment_index/
// constant_id), gl_VertexIndex, gl_InstanceIndex, subpass inputs) as "what at line N",
// or nothing.
std::optional<std::string> vulkan_only_construct(std::string_view text);

}  // namespace shaderbed
