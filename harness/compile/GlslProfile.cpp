#include "compile/GlslProfile.h"

#include <array>
#include <sstream>
#include <vector>

#include "compile/CgTokens.h"

namespace shaderbed {
namespace {

using cg::Token;
using cg::TokenKind;

bool is_opaque_type(std::string_view type) {
  for (std::string_view prefix : {"sampler", "isampler", "usampler", "image", "iimage", "uimage", "texture",
                                  "itexture", "utexture", "subpassInput", "isubpassInput", "usubpassInput",
                                  "atomic_uint"})
    if (type.starts_with(prefix)) return true;
  return false;
}

// Qualifiers that may stand between `uniform` and the type.
bool is_qualifier_word(std::string_view word) {
  static constexpr std::array<std::string_view, 14> words = {
      "uniform", "const",     "lowp",     "mediump",  "highp",     "precise",  "invariant",
      "coherent", "volatile", "restrict", "readonly", "writeonly", "flat",     "smooth"};
  for (std::string_view w : words)
    if (w == word) return true;
  return false;
}

// Index past a parenthesised group starting at tokens[i] == "(".
size_t skip_parens(const std::vector<Token>& tokens, size_t i) {
  int depth = 0;
  for (; i < tokens.size(); ++i) {
    if (tokens[i].is("(")) ++depth;
    if (tokens[i].is(")") && --depth == 0) return i + 1;
  }
  return i;
}

}  // namespace

GlslVersion glsl_version(std::string_view text) {
  GlslVersion v;
  for (const Token& t : cg::lex(text)) {
    if (t.kind != TokenKind::directive) return v;   // #version must come before any code
    std::istringstream in(t.text.substr(1));
    std::string word;
    in >> word;
    if (word != "version") continue;
    v.declared = true;
    v.line = t.physical_line;
    in >> v.number;
    std::string profile;
    in >> profile;
    v.es = profile == "es";
    v.compatibility = profile == "compatibility";
    return v;
  }
  return v;
}

bool is_unversioned_glsl_es(const GlslVersion& version, std::string_view text) {
  if (version.declared) return false;
  const std::vector<Token> tokens = cg::lex(text);
  for (size_t i = 0; i + 1 < tokens.size(); ++i)
    if (tokens[i].is("precision") && tokens[i + 1].is_identifier()) return true;
  return false;
}

bool is_glsl_es(const GlslVersion& version, std::string_view text) {
  return version.es || (version.declared && version.number == 100) || is_unversioned_glsl_es(version, text);
}

bool declares_reduced_precision(std::string_view text) {
  for (const Token& t : cg::lex(text))
    if (t.kind != TokenKind::directive && (t.is("mediump") || t.is("lowp"))) return true;
  return false;
}

bool is_legacy_glsl(const GlslVersion& v) { return !v.es && (v.number <= 140 || v.compatibility); }

bool needs_relaxed_vulkan_rules(std::string_view text) {
  const std::vector<Token> tokens = cg::lex(text);
  int braces = 0;
  bool statement_start = true;
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == TokenKind::directive) continue;
    if (t.is("gl_VertexID") || t.is("gl_InstanceID")) return true;
    if (t.is("{")) ++braces;
    if (t.is("}")) --braces;
    const bool starts = statement_start && braces == 0;
    statement_start = t.is(";") || t.is("{") || t.is("}");
    if (!starts) continue;
    // A top-level statement: [layout(...)] qualifiers... uniform ... type name
    size_t j = i;
    bool uniform = false;
    while (j < tokens.size()) {
      if (tokens[j].is("layout") && j + 1 < tokens.size() && tokens[j + 1].is("(")) {
        j = skip_parens(tokens, j + 1);
        continue;
      }
      if (!tokens[j].is_identifier() || !is_qualifier_word(tokens[j].text)) break;
      uniform = uniform || tokens[j].is("uniform");
      ++j;
    }
    if (!uniform || j >= tokens.size() || !tokens[j].is_identifier()) continue;
    const bool block = j + 1 < tokens.size() && tokens[j + 1].is("{");
    if (!block && !is_opaque_type(tokens[j].text)) return true;
  }
  return false;
}

std::optional<std::string> vulkan_only_construct(std::string_view text) {
  const std::vector<Token> tokens = cg::lex(text);
  const auto at = [](const std::string& what, const Token& t) {
    return what + " at line " + std::to_string(t.physical_line);
  };
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == TokenKind::directive || !t.is_identifier()) continue;
    if (t.is("gl_VertexIndex") || t.is("gl_InstanceIndex")) return at(t.text, t);
    if (t.text.starts_with("subpassInput") || t.text.starts_with("isubpassInput") ||
        t.text.starts_with("usubpassInput"))
      return at(t.text, t);
    if (!t.is("layout") || i + 1 >= tokens.size() || !tokens[i + 1].is("(")) continue;
    const size_t end = skip_parens(tokens, i + 1);
    for (size_t j = i + 2; j < end; ++j)
      for (std::string_view word : {"set", "push_constant", "input_attachment_index", "constant_id"})
        if (tokens[j].is(word)) return at("layout(" + std::string(word) + ")", tokens[j]);
  }
  return std::nullopt;
}

}  // namespace shaderbed
