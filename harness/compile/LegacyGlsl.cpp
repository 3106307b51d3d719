#include "compile/LegacyGlsl.h"

#include <array>
#include <cctype>
#include <vector>

#include "compile/CgTokens.h"

namespace shaderbed {
namespace {

using cg::Token;
using cg::TokenKind;

constexpr int kMaxTextureCoords = 8;   // gl_MaxTextureCoords in Mesa

struct Unsupported {
  std::string_view name;
  std::string_view why;
};
constexpr Unsupported kUnsupported[] = {
    {"gl_BackMaterial", "two-sided lighting"},
    {"gl_BackLightProduct", "two-sided lighting"},
    {"gl_BackLightModelProduct", "two-sided lighting"},
    {"gl_BackColor", "two-sided lighting"},
    {"gl_BackSecondaryColor", "two-sided lighting"},
    {"gl_SecondaryColor", "secondary colours"},
    {"gl_FrontSecondaryColor", "secondary colours"},
    {"gl_FogCoord", "fog"},
    {"gl_FogFragCoord", "fog"},
    {"gl_Fog", "fog"},
    {"gl_ClipVertex", "user clip planes"},
    {"gl_ClipPlane", "user clip planes"},
    {"gl_TextureMatrix", "texture matrices"},
    {"gl_TextureMatrixInverse", "texture matrices"},
    {"gl_TextureMatrixTranspose", "texture matrices"},
    {"gl_TextureMatrixInverseTranspose", "texture matrices"},
    {"gl_NormalScale", "normal rescaling"},
    {"gl_EyePlaneS", "texture coordinate generation"},
    {"gl_ObjectPlaneS", "texture coordinate generation"},
    {"gl_TextureEnvColor", "texture environments"},
    {"gl_Point", "point parameters"},
    {"shadow1D", "depth-comparison lookups"},
    {"shadow2D", "depth-comparison lookups"},
    {"shadow1DProj", "depth-comparison lookups"},
    {"shadow2DProj", "depth-comparison lookups"},
    {"shadow1DLod", "depth-comparison lookups"},
    {"shadow2DLod", "depth-comparison lookups"},
};

// GLSL 1.10/1.20 lookups and their 4.50 names.
constexpr std::pair<std::string_view, std::string_view> kLookups[] = {
    {"texture1D", "texture"},         {"texture2D", "texture"},         {"texture3D", "texture"},
    {"textureCube", "texture"},       {"texture1DProj", "textureProj"}, {"texture2DProj", "textureProj"},
    {"texture3DProj", "textureProj"}, {"texture1DLod", "textureLod"},   {"texture2DLod", "textureLod"},
    {"texture3DLod", "textureLod"},   {"textureCubeLod", "textureLod"}, {"texture1DProjLod", "textureProjLod"},
    {"texture2DProjLod", "textureProjLod"}, {"texture3DProjLod", "textureProjLod"},
};

// Words free in GLSL 1.10/1.20 that 4.50 reserves or declares as a built-in function an
// author's variable would hide.
constexpr std::string_view kNewWords[] = {
    "texture", "sample",   "flat",     "smooth",   "noperspective", "layout",   "patch",  "subroutine",
    "buffer",  "shared",   "coherent", "restrict", "readonly",      "writeonly", "resource", "precise",
    "uint",    "uvec2",    "uvec3",    "uvec4",    "switch",        "case",      "default",  "common",
    "partition", "active", "filter",   "superp"};

constexpr std::string_view kMatrices[] = {"ModelViewMatrix", "ProjectionMatrix", "ModelViewProjectionMatrix"};
constexpr std::string_view kMatrixForms[] = {"", "Inverse", "Transpose", "InverseTranspose"};

// gl_LightSource[n] members: type, or "" for the derived ones.
constexpr std::pair<std::string_view, std::string_view> kLightMembers[] = {
    {"ambient", "vec4"},           {"diffuse", "vec4"},           {"specular", "vec4"},
    {"position", "vec4"},          {"spotDirection", "vec3"},     {"spotExponent", "float"},
    {"spotCutoff", "float"},       {"constantAttenuation", "float"}, {"linearAttenuation", "float"},
    {"quadraticAttenuation", "float"}, {"spotCosCutoff", ""},     {"halfVector", ""}};
constexpr std::pair<std::string_view, std::string_view> kMaterialMembers[] = {
    {"emission", "vec4"}, {"ambient", "vec4"}, {"diffuse", "vec4"}, {"specular", "vec4"}, {"shininess", "float"}};

std::string_view member_type(const auto& table, std::string_view member) {
  for (const auto& [name, type] : table)
    if (name == member) return type;
  return "?";
}

class Translator {
 public:
  Translator(const ShaderSource& source, const GlslVersion& version)
      : source_(source), version_(version), tokens_(cg::lex(source.text)) {}

  Result<LegacyGlslTranslation> run() {
    Token* version_directive = nullptr;
    for (size_t i = 0; i < tokens_.size() && !error_; ++i) {
      Token& t = tokens_[i];
      if (t.kind == TokenKind::directive) {
        if (is_version(t)) version_directive = &t;
        else if (is_define(t)) rewrite_define(t);
        continue;
      }
      if (t.is_identifier()) rewrite(i);
    }
    if (error_) return std::unexpected(*error_);

    std::string header = "#version 450\n";
    for (const auto& [name, declaration] : declarations_) header += declaration + "\n";
    LegacyGlslTranslation out;
    if (version_directive) {
      version_directive->text = header + "#line " + std::to_string(version_directive->physical_line + 1);
      out.text = cg::rebuild(source_.text, tokens_);
    } else {
      out.text = header + "#line 1\n" + cg::rebuild(source_.text, tokens_);
    }
    out.legacy_names = std::move(legacy_names_);
    return out;
  }

 private:
  bool vertex() const { return source_.stage == Stage::vertex; }

  static std::string directive_word(const Token& t) {
    size_t i = 1;
    while (i < t.text.size() && (t.text[i] == ' ' || t.text[i] == '\t')) ++i;
    size_t j = i;
    while (j < t.text.size() && std::isalpha(static_cast<unsigned char>(t.text[j]))) ++j;
    return t.text.substr(i, j - i);
  }
  static bool is_version(const Token& t) { return directive_word(t) == "version"; }
  static bool is_define(const Token& t) { return directive_word(t) == "define"; }

  void fail_at(const Token& t, std::string message) {
    if (!error_)
      error_ = Error{.message = std::move(message), .file = source_.path, .line = t.physical_line, .stage = ErrorStage::compile};
  }

  void declare(const std::string& name, std::string declaration, std::string legacy = "") {
    declarations_.try_emplace(name, std::move(declaration));
    if (!legacy.empty()) legacy_names_.try_emplace(name, std::move(legacy));
  }
  std::string uniform(std::string_view type, const std::string& name, const std::string& legacy) {
    declare(name, "uniform " + std::string(type) + " " + name + ";", legacy);
    return name;
  }
  std::string light(const std::string& index, std::string_view member) {
    return uniform(member_type(kLightMembers, member), "sbgl_LightSource" + index + "_" + std::string(member),
                   "gl_LightSource[" + index + "]." + std::string(member));
  }
  std::string material(std::string_view member) {
    return uniform(member_type(kMaterialMembers, member), "sbgl_FrontMaterial_" + std::string(member),
                   "gl_FrontMaterial." + std::string(member));
  }

  // `name [ literal ] . member` at tokens_[i]: the literal and the member, with the
  // tokens after the name dropped; false (and an error) when the shape is different.
  bool indexed_member(size_t i, std::string& index, std::string& member) {
    const Token& t = tokens_[i];
    if (i + 5 >= tokens_.size() || !tokens_[i + 1].is("[") || tokens_[i + 2].kind != TokenKind::number ||
        !tokens_[i + 3].is("]") || !tokens_[i + 4].is(".") || !tokens_[i + 5].is_identifier()) {
      fail_at(t, t.text + " is supported only as " + t.text +
                     "[n].member with a literal n (the dialect gives each member its own uniform)");
      return false;
    }
    index = tokens_[i + 2].text;
    member = tokens_[i + 5].text;
    for (size_t k = i + 1; k <= i + 5; ++k) tokens_[k].removed = true;
    return true;
  }
  bool plain_member(size_t i, std::string& member) {
    const Token& t = tokens_[i];
    if (i + 2 >= tokens_.size() || !tokens_[i + 1].is(".") || !tokens_[i + 2].is_identifier()) {
      fail_at(t, t.text + " is supported only as " + t.text + ".member");
      return false;
    }
    member = tokens_[i + 2].text;
    tokens_[i + 1].removed = tokens_[i + 2].removed = true;
    return true;
  }

  void rewrite(size_t i) {
    Token& t = tokens_[i];
    const std::string name = t.text;
    if (name.starts_with("gl_") || name.starts_with("shadow"))  // as every kUnsupported name does
      for (const Unsupported& u : kUnsupported)
        if (name == u.name || (u.name.starts_with("gl_EyePlane") && name.starts_with("gl_EyePlane")) ||
            (u.name.starts_with("gl_ObjectPlane") && name.starts_with("gl_ObjectPlane")))
          return fail_at(t, name + " (" + std::string(u.why) + ") is not supported by the legacy-GLSL dialect");
    if (name.starts_with("gl_MultiTexCoord") && name != "gl_MultiTexCoord0")
      return fail_at(t, name + " is not supported by the legacy-GLSL dialect: meshes have one texture coordinate set");
    for (const auto& [legacy, modern] : kLookups)
      if (name == legacy) {
        t.text = modern;
        return;
      }
    if (version_.number <= 120)
      for (std::string_view word : kNewWords)
        if (name == word) {
          t.text = "sb_" + name;
          legacy_names_.try_emplace(t.text, name);
          return;
        }
    if (name == "attribute") {
      if (vertex()) t.text = "in";
      return;
    }
    if (name == "varying") {
      t.text = vertex() ? "out" : "in";
      return;
    }
    if (!name.starts_with("gl_") && name != "ftransform") return;

    if (vertex() && name == "gl_Vertex") t.text = input("vec4", "sbgl_Vertex", name);
    else if (vertex() && name == "gl_Normal") t.text = input("vec3", "sbgl_Normal", name);
    else if (vertex() && name == "gl_Color") t.text = input("vec4", "sbgl_Color", name);
    else if (vertex() && name == "gl_MultiTexCoord0") t.text = input("vec4", "sbgl_MultiTexCoord0", name);
    else if (vertex() && name == "ftransform") rewrite_ftransform(i);
    else if (vertex() && name == "gl_FrontColor") t.text = varying("vec4 sbgl_FrontColor", "sbgl_FrontColor");
    else if (!vertex() && name == "gl_Color") t.text = varying("vec4 sbgl_FrontColor", "sbgl_FrontColor");
    else if (name == "gl_TexCoord")
      t.text = varying("vec4 sbgl_TexCoord[" + std::to_string(kMaxTextureCoords) + "]", "sbgl_TexCoord");
    else if (!vertex() && name == "gl_FragColor") {
      declare("sbgl_FragColor", "layout(location = 0) out vec4 sbgl_FragColor;");
      t.text = "sbgl_FragColor";
    } else if (!vertex() && name == "gl_FragData") {
      declare("sbgl_FragData", "layout(location = 0) out vec4 sbgl_FragData[1];");
      t.text = "sbgl_FragData";
    } else if (name == "gl_NormalMatrix") t.text = uniform("mat3", "sbgl_NormalMatrix", name);
    else if (name == "gl_LightSource") rewrite_light(i);
    else if (name == "gl_FrontMaterial") {
      std::string member;
      if (!plain_member(i, member)) return;
      if (member_type(kMaterialMembers, member) == "?")
        return fail_at(t, "gl_FrontMaterial has no member '" + member + "'");
      t.text = material(member);
    } else if (name == "gl_LightModel") {
      std::string member;
      if (!plain_member(i, member)) return;
      if (member != "ambient") return fail_at(t, "gl_LightModel has no member '" + member + "'");
      t.text = uniform("vec4", "sbgl_LightModel_ambient", "gl_LightModel.ambient");
    } else if (name == "gl_FrontLightProduct") rewrite_light_product(i);
    else if (name == "gl_FrontLightModelProduct") {
      std::string member;
      if (!plain_member(i, member)) return;
      if (member != "sceneColor") return fail_at(t, "gl_FrontLightModelProduct has no member '" + member + "'");
      // Mesa: ecm + acm * acs, alpha the material's diffuse alpha.
      const std::string ambient = uniform("vec4", "sbgl_LightModel_ambient", "gl_LightModel.ambient");
      t.text = "vec4(" + material("emission") + ".rgb + " + material("ambient") + ".rgb * " + ambient + ".rgb, " +
               material("diffuse") + ".a)";
    } else {
      for (std::string_view matrix : kMatrices)
        for (std::string_view form : kMatrixForms)
          if (name == "gl_" + std::string(matrix) + std::string(form))
            t.text = uniform("mat4", "sb" + name, name);
    }
  }

  std::string input(const char* type, const std::string& dialect, const std::string& legacy) {
    declare(dialect, "in " + std::string(type) + " " + dialect + ";", legacy);
    return dialect;
  }
  std::string varying(const std::string& declaration, const std::string& dialect) {
    declare(dialect, std::string(vertex() ? "out " : "in ") + declaration + ";");
    return dialect;
  }

  void rewrite_ftransform(size_t i) {
    if (i + 2 >= tokens_.size() || !tokens_[i + 1].is("(") || !tokens_[i + 2].is(")"))
      return fail_at(tokens_[i], "ftransform takes no arguments");
    const std::string mvp = uniform("mat4", "sbgl_ModelViewProjectionMatrix", "gl_ModelViewProjectionMatrix");
    tokens_[i].text = "(" + mvp + " * " + input("vec4", "sbgl_Vertex", "gl_Vertex") + ")";
    tokens_[i + 1].removed = tokens_[i + 2].removed = true;
  }

  void rewrite_light(size_t i) {
    std::string index, member;
    if (!indexed_member(i, index, member)) return;
    Token& t = tokens_[i];
    const std::string_view type = member_type(kLightMembers, member);
    if (type == "?") return fail_at(t, "gl_LightSource has no member '" + member + "'");
    if (member == "halfVector")
      return fail_at(t, "gl_LightSource[" + index +
                            "].halfVector is not supported: GL derives it for a viewer along +z of GL's eye space, "
                            "which is not the scene's view space; compute the half vector in the shader");
    if (member == "spotCosCutoff") {
      t.text = "cos(radians(" + light(index, "spotCutoff") + "))";
      return;
    }
    t.text = light(index, member);
  }

  void rewrite_light_product(size_t i) {
    std::string index, member;
    if (!indexed_member(i, index, member)) return;
    Token& t = tokens_[i];
    if (member != "ambient" && member != "diffuse" && member != "specular")
      return fail_at(t, "gl_FrontLightProduct has no member '" + member + "'");
    // Mesa: light * material per rgb channel, alpha the material's.
    const std::string m = material(member);
    t.text = "vec4(" + m + ".rgb * " + light(index, member) + ".rgb, " + m + ".a)";
  }

  // Simple renames inside a #define body (gl_Vertex, texture2D, varying, ...).
  void rewrite_define(Token& directive) {
    const ShaderSource body{.stage = source_.stage, .path = source_.path, .text = directive.text.substr(1)};
    Translator inner(body, version_);
    std::vector<Token>& tokens = inner.tokens_;
    for (size_t i = 0; i < tokens.size(); ++i)
      if (tokens[i].is_identifier()) inner.rewrite(i);
    if (inner.error_) {
      Error e = *inner.error_;
      e.line = directive.physical_line;
      error_ = e;
      return;
    }
    directive.text = "#" + cg::rebuild(body.text, tokens);
    for (auto& [name, declaration] : inner.declarations_) declarations_.try_emplace(name, declaration);
    for (auto& [name, legacy] : inner.legacy_names_) legacy_names_.try_emplace(name, legacy);
  }

  const ShaderSource& source_;
  GlslVersion version_;
  std::vector<Token> tokens_;
  std::map<std::string, std::string> declarations_;   // by dialect name
  std::map<std::string, std::string> legacy_names_;
  std::optional<Error> error_;
};

}  // namespace

Result<LegacyGlslTranslation> translate_legacy_glsl(const ShaderSource& source, const GlslVersion& version) {
  return Translator(source, version).run();
}

std::optional<std::string> legacy_glsl_default_binding(std::string_view name) {
  if (name == "gl_NormalMatrix") return "normal_matrix_view";
  constexpr std::pair<std::string_view, std::string_view> quantities[] = {
      {"gl_ModelViewProjectionMatrix", "transform"}, {"gl_ModelViewMatrix", "world_view"},
      {"gl_ProjectionMatrix", "projection"}};
  constexpr std::pair<std::string_view, std::string_view> forms[] = {
      {"InverseTranspose", "_inverse_transpose"}, {"Inverse", "_inverse"}, {"Transpose", "_transpose"}, {"", ""}};
  for (const auto& [legacy, quantity] : quantities) {
    if (!name.starts_with(legacy)) continue;
    const std::string_view form = name.substr(legacy.size());
    for (const auto& [suffix, quantity_suffix] : forms)
      if (form == suffix) return std::string(quantity) + std::string(quantity_suffix);
  }
  return std::nullopt;
}

}  // namespace shaderbed
