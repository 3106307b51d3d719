#include "compile/EffectStates.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <optional>

#include "core/AsciiCase.h"

namespace shaderbed {
namespace {

Error state_error(const EffectAssignment& a, const std::string& path, std::string message) {
  return Error{.message = std::move(message), .file = path, .line = a.line, .stage = ErrorStage::compile};
}

// The value as one upper-case word without D3D's enum prefix (D3DCULL_CCW -> CCW), or
// "" when it is not a single word or number.
std::string word(const EffectAssignment& a, std::string_view prefix) {
  if (a.value_tokens.size() != 1) return {};
  std::string w = ascii_upper(a.value_tokens[0]);
  if (w.starts_with(prefix)) w = w.substr(prefix.size());
  return w;
}

template <typename T>
Result<T> lookup(const EffectAssignment& a, const std::string& path, std::string_view prefix,
                 const std::map<std::string, T>& values) {
  const std::string w = word(a, prefix);
  if (auto it = values.find(w); it != values.end()) return it->second;
  std::string expected;
  for (const auto& [name, value] : values)
    if (!std::isdigit(static_cast<unsigned char>(name[0]))) expected += (expected.empty() ? "" : ", ") + name;
  return std::unexpected(
      state_error(a, path, "state '" + a.name + "' = '" + a.value + "' is not supported (expected " + expected + ")"));
}

Result<bool> boolean(const EffectAssignment& a, const std::string& path) {
  return lookup<bool>(a, path, "D3DZB_", {{"TRUE", true}, {"FALSE", false}, {"1", true}, {"0", false}});
}

bool equals_name(const std::string& a, std::string_view b) { return ascii_upper(a) == ascii_upper(b); }

const std::map<std::string, TextureFilter> kFilters = {
    {"POINT", TextureFilter::nearest}, {"LINEAR", TextureFilter::linear}, {"ANISOTROPIC", TextureFilter::linear},
    {"1", TextureFilter::nearest},     {"2", TextureFilter::linear},      {"3", TextureFilter::linear}};
const std::map<std::string, MipFilter> kMipFilters = {{"NONE", MipFilter::none}, {"POINT", MipFilter::nearest},
                                                      {"LINEAR", MipFilter::linear}, {"0", MipFilter::none},
                                                      {"1", MipFilter::nearest},  {"2", MipFilter::linear}};
const std::map<std::string, AddressMode> kAddress = {
    {"WRAP", AddressMode::wrap}, {"MIRROR", AddressMode::mirror}, {"CLAMP", AddressMode::clamp},
    {"BORDER", AddressMode::border}, {"1", AddressMode::wrap},      {"2", AddressMode::mirror},
    {"3", AddressMode::clamp},       {"4", AddressMode::border}};

// BorderColor: a D3DCOLOR 0xAARRGGBB, or float4(r, g, b, a) / {r, g, b, a}.
Result<void> border_colour(const EffectAssignment& a, const std::string& path, float out[4]) {
  if (a.value_tokens.size() == 1) {
    char* end = nullptr;
    const unsigned long argb = std::strtoul(a.value_tokens[0].c_str(), &end, 0);
    if (end && *end == '\0') {
      out[0] = float((argb >> 16) & 0xff) / 255.0f;
      out[1] = float((argb >> 8) & 0xff) / 255.0f;
      out[2] = float(argb & 0xff) / 255.0f;
      out[3] = float((argb >> 24) & 0xff) / 255.0f;
      return {};
    }
  }
  std::vector<float> numbers;
  for (const std::string& t : a.value_tokens) {
    if (t == "float4" || t == "(" || t == ")" || t == "{" || t == "}" || t == ",") continue;
    char* end = nullptr;
    const float f = std::strtof(t.c_str(), &end);
    if (!end || (*end != '\0' && *end != 'f' && *end != 'F'))
      return std::unexpected(state_error(a, path, "BorderColor = '" + a.value + "': expected 0xAARRGGBB or float4(r, g, b, a)"));
    numbers.push_back(f);
  }
  if (numbers.size() != 4)
    return std::unexpected(state_error(a, path, "BorderColor = '" + a.value + "': expected 0xAARRGGBB or float4(r, g, b, a)"));
  std::copy(numbers.begin(), numbers.end(), out);
  return {};
}

// `compile vs_2_0 VS(a, b)` or SM4's `CompileShader(vs_4_0, VS(a, b))`.
Result<EffectShaderCompile> shader_compile(const EffectAssignment& a, const std::string& path) {
  const std::vector<std::string>& v = a.value_tokens;
  EffectShaderCompile out{.line = a.line};
  std::size_t call = 0;
  if (v.size() >= 3 && v[0] == "compile") {
    out.profile = v[1];
    call = 2;
  } else if (v.size() >= 6 && v[0] == "CompileShader" && v[1] == "(" && v[3] == ",") {
    out.profile = v[2];
    call = 4;
  } else if (v.size() == 1 && (ascii_upper(v[0]) == "NULL")) {
    return std::unexpected(state_error(a, path, a.name + " = NULL: shaderbed needs a vertex and a pixel shader "
                                                "(no fixed-function pipeline)"));
  } else if (!v.empty() && v[0] == "asm") {
    return std::unexpected(state_error(a, path, "effect feature 'asm' shader is not supported by shaderbed's "
                                                "effect layer (no D3D assembler; write HLSL and `compile` it)"));
  } else {
    return std::unexpected(state_error(a, path, a.name + " = '" + a.value + "': expected 'compile PROFILE Function(...)'"));
  }
  const std::string profile = out.profile;
  const bool vertex = equals_name(a.name, "VertexShader") || equals_name(a.name, "SetVertexShader");
  const std::string want = vertex ? "vs_" : "ps_";
  if (!profile.starts_with(want) || profile.size() < 4 || !std::isdigit(static_cast<unsigned char>(profile[3])))
    return std::unexpected(state_error(a, path, a.name + " is compiled with profile '" + profile + "' (expected " +
                                                    want + "2_0, " + want + "3_0, " + want + "4_0, ...)"));
  out.shader_model = profile[3] - '0';
  if (call >= v.size() || call + 1 >= v.size() || v[call + 1] != "(")
    return std::unexpected(state_error(a, path, a.name + " = '" + a.value + "': expected a function call after the profile"));
  out.function = v[call];
  // Arguments: the tokens between the call's parentheses, split at depth-0 commas.
  int depth = 0;
  std::string arg;
  std::size_t k = call + 2;
  for (; k < v.size(); ++k) {
    const std::string& t = v[k];
    if (depth == 0 && t == ")") break;
    if (t == "(" || t == "[" || t == "{") ++depth;
    if (t == ")" || t == "]" || t == "}") --depth;
    if (depth == 0 && t == ",") {
      out.arguments.push_back(arg);
      arg.clear();
      continue;
    }
    arg += (arg.empty() ? "" : " ") + t;
  }
  if (!arg.empty()) out.arguments.push_back(arg);
  if (k >= v.size())
    return std::unexpected(state_error(a, path, a.name + " = '" + a.value + "': unbalanced parentheses"));
  return out;
}

const std::map<std::string, BlendFactor> kBlendFactors = {
    {"ZERO", BlendFactor::zero},
    {"ONE", BlendFactor::one},
    {"SRCCOLOR", BlendFactor::src_colour},
    {"INVSRCCOLOR", BlendFactor::inv_src_colour},
    {"SRCALPHA", BlendFactor::src_alpha},
    {"INVSRCALPHA", BlendFactor::inv_src_alpha},
    {"DESTALPHA", BlendFactor::dest_alpha},
    {"INVDESTALPHA", BlendFactor::inv_dest_alpha},
    {"DESTCOLOR", BlendFactor::dest_colour},
    {"INVDESTCOLOR", BlendFactor::inv_dest_colour},
    {"SRCALPHASAT", BlendFactor::src_alpha_saturate},
    {"1", BlendFactor::zero},
    {"2", BlendFactor::one},
    {"3", BlendFactor::src_colour},
    {"4", BlendFactor::inv_src_colour},
    {"5", BlendFactor::src_alpha},
    {"6", BlendFactor::inv_src_alpha},
    {"7", BlendFactor::dest_alpha},
    {"8", BlendFactor::inv_dest_alpha},
    {"9", BlendFactor::dest_colour},
    {"10", BlendFactor::inv_dest_colour},
    {"11", BlendFactor::src_alpha_saturate}};

const std::map<std::string, CompareOp> kCompare = {
    {"NEVER", CompareOp::never},         {"LESS", CompareOp::less},         {"EQUAL", CompareOp::equal},
    {"LESSEQUAL", CompareOp::less_equal}, {"GREATER", CompareOp::greater},   {"NOTEQUAL", CompareOp::not_equal},
    {"GREATEREQUAL", CompareOp::greater_equal}, {"ALWAYS", CompareOp::always}, {"1", CompareOp::never},
    {"2", CompareOp::less},              {"3", CompareOp::equal},           {"4", CompareOp::less_equal},
    {"5", CompareOp::greater},           {"6", CompareOp::not_equal},       {"7", CompareOp::greater_equal},
    {"8", CompareOp::always}};

// Fixed-function states that cannot change what shaderbed draws once both shaders are
// bound: the vertex pipeline's lighting and material sources, and switches of features
// shaderbed's float target does not have.
bool ignorable_whatever_its_value(const std::string& name) {
  static const char* names[] = {"LIGHTING",     "SPECULARENABLE",           "COLORVERTEX",
                                "NORMALIZENORMALS", "LOCALVIEWER",          "DIFFUSEMATERIALSOURCE",
                                "SPECULARMATERIALSOURCE", "AMBIENTMATERIALSOURCE", "EMISSIVEMATERIALSOURCE",
                                "AMBIENT",      "DITHERENABLE",             "MULTISAMPLEANTIALIAS"};
  return std::ranges::any_of(names, [&](const char* n) { return name == n; });
}

// States harmless only at their default (the feature off, or every channel written).
std::optional<std::string> default_only(const std::string& name) {
  static const std::map<std::string, std::string> defaults = {
      {"FOGENABLE", "FALSE"},        {"ALPHATESTENABLE", "FALSE"}, {"STENCILENABLE", "FALSE"},
      {"SCISSORTESTENABLE", "FALSE"}, {"SEPARATEALPHABLENDENABLE", "FALSE"}, {"SRGBWRITEENABLE", "FALSE"},
      {"COLORWRITEENABLE", "15"},    {"CLIPPLANEENABLE", "0"}};
  if (auto it = defaults.find(name); it != defaults.end()) return it->second;
  return std::nullopt;
}

bool is_default_value(const std::string& value, const std::string& default_value) {
  const std::string v = ascii_upper(value);
  if (default_value == "FALSE") return v == "FALSE" || v == "0";
  if (default_value == "15")
    return v == "15" || v == "0XF" || v == "0X0F" || v == "0X0000000F" ||
           v == "RED | GREEN | BLUE | ALPHA";
  return v == default_value;
}

}  // namespace

Result<void> apply_sampler_state(const EffectAssignment& a, EffectSampler& s, const std::string& path,
                                 std::vector<EffectNote>& notes) {
  const std::string name = ascii_upper(a.name);
  SamplerSettings& out = s.settings;
  if (a.index >= 0)
    return std::unexpected(state_error(a, path, "sampler state '" + a.name + "[" + std::to_string(a.index) +
                                                    "]' of sampler '" + s.name + "' takes no index"));
  if (name == "TEXTURE") {
    std::string texture;
    for (const std::string& t : a.value_tokens)
      if (t != "<" && t != ">" && t != "(" && t != ")") texture += t;
    s.texture = texture;
    return {};
  }
  if (name == "MINFILTER" || name == "MAGFILTER") {
    auto f = lookup(a, path, "D3DTEXF_", kFilters);
    if (!f) return std::unexpected(f.error());
    if (word(a, "D3DTEXF_") == "ANISOTROPIC" || word(a, "D3DTEXF_") == "3")
      notes.push_back({a.line, "sampler '" + s.name + "': " + a.name +
                                   " = ANISOTROPIC drawn as LINEAR (shaderbed's samplers have no anisotropy)"});
    (name == "MINFILTER" ? out.min_filter : out.mag_filter) = *f;
    return {};
  }
  if (name == "MIPFILTER") {
    auto f = lookup(a, path, "D3DTEXF_", kMipFilters);
    if (!f) return std::unexpected(f.error());
    out.mip_filter = *f;
    return {};
  }
  if (name == "ADDRESSU" || name == "ADDRESSV" || name == "ADDRESSW") {
    auto m = lookup(a, path, "D3DTADDRESS_", kAddress);
    if (!m) return std::unexpected(m.error());
    (name == "ADDRESSU" ? out.address_u : name == "ADDRESSV" ? out.address_v : out.address_w) = *m;
    return {};
  }
  if (name == "BORDERCOLOR") return border_colour(a, path, out.border_color);
  if (name == "SRGBTEXTURE") {
    auto b = boolean(a, path);
    if (!b) return std::unexpected(b.error());
    out.srgb = *b;
    return {};
  }
  if (name == "MAXANISOTROPY") {
    notes.push_back({a.line, "sampler '" + s.name + "': MaxAnisotropy ignored (no anisotropic filtering)"});
    return {};
  }
  if (name == "MIPMAPLODBIAS" || name == "MAXMIPLEVEL") {
    const std::string w = word(a, "");
    if (w == "0" || w == "0.0" || w == "0.0F" || w == "0.F" || w == "0F") return {};
    return std::unexpected(state_error(a, path, "sampler state '" + a.name + "' = '" + a.value + "' of sampler '" +
                                                    s.name + "' is not supported (only 0)"));
  }
  return std::unexpected(state_error(a, path, "unknown sampler state '" + a.name + "' in sampler '" + s.name +
                                                  "' (shaderbed knows Texture, MinFilter, MagFilter, MipFilter, "
                                                  "AddressU, AddressV, AddressW, BorderColor, SRGBTexture)"));
}

Result<EffectPassStates> interpret_pass(const EffectPass& pass, const std::string& path) {
  EffectPassStates out;
  RenderState& rs = out.render_state;
  // D3D9's defaults where they differ from shaderbed's: CullMode CCW, ZFunc LESSEQUAL.
  rs.cull = CullMode::ccw;
  rs.depth_compare = CompareOp::less_equal;
  for (const EffectAssignment& a : pass.states) {
    const std::string name = ascii_upper(a.name);
    if (a.index >= 0)
      return std::unexpected(state_error(a, path, "render state '" + a.name + "[" + std::to_string(a.index) +
                                                      "]' is not supported (fixed-function texture stages; shaders "
                                                      "sample through sampler_state samplers)"));
    if (name == "VERTEXSHADER" || name == "PIXELSHADER" || name == "SETVERTEXSHADER" || name == "SETPIXELSHADER") {
      auto compiled = shader_compile(a, path);
      if (!compiled) return std::unexpected(compiled.error());
      (name.find("VERTEX") != std::string::npos ? out.vertex : out.pixel) = std::move(*compiled);
      continue;
    }
    if (name == "SETGEOMETRYSHADER" || name == "GEOMETRYSHADER" || name == "SETHULLSHADER" ||
        name == "SETDOMAINSHADER" || name == "SETCOMPUTESHADER") {
      if (word(a, "") == "NULL" || word(a, "") == "0") continue;
      return std::unexpected(state_error(a, path, "render state '" + a.name + "' is not supported (shaderbed draws "
                                                      "a vertex and a pixel shader only)"));
    }
    if (name == "CULLMODE") {
      auto c = lookup<CullMode>(a, path, "D3DCULL_",
                                {{"NONE", CullMode::none}, {"CW", CullMode::cw}, {"CCW", CullMode::ccw},
                                 {"1", CullMode::none}, {"2", CullMode::cw}, {"3", CullMode::ccw}});
      if (!c) return std::unexpected(c.error());
      rs.cull = *c;
    } else if (name == "ZENABLE") {
      auto b = boolean(a, path);
      if (!b) return std::unexpected(b.error());
      rs.depth_test = *b;
    } else if (name == "ZWRITEENABLE") {
      auto b = boolean(a, path);
      if (!b) return std::unexpected(b.error());
      rs.depth_write = *b;
    } else if (name == "ZFUNC") {
      auto c = lookup(a, path, "D3DCMP_", kCompare);
      if (!c) return std::unexpected(c.error());
      rs.depth_compare = *c;
    } else if (name == "ALPHABLENDENABLE") {
      auto b = boolean(a, path);
      if (!b) return std::unexpected(b.error());
      rs.blend = *b;
    } else if (name == "SRCBLEND" || name == "DESTBLEND") {
      auto f = lookup(a, path, "D3DBLEND_", kBlendFactors);
      if (!f) return std::unexpected(f.error());
      (name == "SRCBLEND" ? rs.src_blend : rs.dest_blend) = *f;
    } else if (name == "BLENDOP") {
      auto op = lookup<BlendOp>(a, path, "D3DBLENDOP_",
                                {{"ADD", BlendOp::add}, {"SUBTRACT", BlendOp::subtract},
                                 {"REVSUBTRACT", BlendOp::reverse_subtract}, {"MIN", BlendOp::min},
                                 {"MAX", BlendOp::max}, {"1", BlendOp::add}, {"2", BlendOp::subtract},
                                 {"3", BlendOp::reverse_subtract}, {"4", BlendOp::min}, {"5", BlendOp::max}});
      if (!op) return std::unexpected(op.error());
      rs.blend_op = *op;
    } else if (name == "FILLMODE") {
      auto f = lookup<FillMode>(a, path, "D3DFILL_",
                                {{"POINT", FillMode::point}, {"WIREFRAME", FillMode::wireframe},
                                 {"SOLID", FillMode::solid}, {"1", FillMode::point}, {"2", FillMode::wireframe},
                                 {"3", FillMode::solid}});
      if (!f) return std::unexpected(f.error());
      rs.fill = *f;
    } else if (ignorable_whatever_its_value(name)) {
      out.notes.push_back({a.line, "render state " + a.name + " ignored: fixed-function only, it cannot change an "
                                   "image drawn with a vertex and a pixel shader"});
    } else if (auto default_value = default_only(name)) {
      if (!is_default_value(a.value, *default_value))
        return std::unexpected(state_error(a, path, "render state '" + a.name + "' = '" + a.value +
                                                        "' is not supported by shaderbed (only its default, " +
                                                        *default_value + ")"));
      out.notes.push_back({a.line, "render state " + a.name + " = " + a.value + " is the default: nothing to do"});
    } else {
      return std::unexpected(state_error(a, path, "unknown render state '" + a.name + "' (not one shaderbed applies: "
                                                  "CullMode, ZEnable, ZWriteEnable, ZFunc, AlphaBlendEnable, SrcBlend, "
                                                  "DestBlend, BlendOp, FillMode)"));
    }
  }
  return out;
}

}  // namespace shaderbed
