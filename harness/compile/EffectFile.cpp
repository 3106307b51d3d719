#include "compile/EffectFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>

#include "compile/CgTokens.h"
#include "compile/EffectConditionals.h"
#include "compile/EffectStates.h"

namespace shaderbed {
namespace {

using cg::Token;
using cg::TokenKind;

bool is_technique_keyword(const Token& t) {
  return t.is_identifier() && (t.is("technique") || t.is("technique10") || t.is("technique11"));
}

// DX9 texture objects; SM4's Texture2D & co. are HLSL glslang reads, not effect syntax.
bool is_dx9_texture_type(const Token& t) {
  static const std::set<std::string> types = {"texture", "texture1D", "texture2D", "texture3D", "textureCUBE",
                                              "Texture"};
  return t.is_identifier() && types.contains(t.text);
}

bool is_effect_sampler_type(const std::string& s) {
  return s == "sampler" || s == "sampler1D" || s == "sampler2D" || s == "sampler3D" || s == "samplerCUBE";
}

// "float3" -> 3, "half" -> 1, "float4x4" or "texture" -> 0 (no initial value is read).
int numeric_components(const std::string& type) {
  for (std::string_view base : {"float", "half", "double", "int", "uint", "bool", "min16float", "min10float",
                                "min16int", "min16uint"}) {
    if (!type.starts_with(base)) continue;
    const std::string rest = type.substr(base.size());
    if (rest.empty()) return 1;
    if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return rest[0] - '0';
  }
  return 0;
}

// One element of an initialiser, its tokens joined: "-0.5f" -> -0.5, "true" -> 1.
std::optional<double> initial_number(const std::string& text) {
  if (text == "true") return 1.0;
  if (text == "false") return 0.0;
  std::string number = text;
  while (!number.empty() && std::string_view("fFhHlLuU").find(number.back()) != std::string_view::npos &&
         number.find_first_of("xX") == std::string::npos)
    number.pop_back();
  if (number.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

bool is_storage_qualifier(const Token& t) {
  return t.is_identifier() && (t.is("uniform") || t.is("static") || t.is("shared") || t.is("extern") ||
                               t.is("const") || t.is("volatile") || t.is("inline"));
}

// One top-level item: [begin, end) tokens, ending at a `;` or a function/technique body.
struct Item {
  std::size_t begin = 0, end = 0;
  bool has_body = false;     // a `{ ... }` body at depth 0 (function, technique, cbuffer)
  std::size_t body_open = 0; // index of that body's `{`
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& path) : text_(text), path_(path), tokens_(cg::lex(text)) {
    cg::assign_positions(tokens_, path);
    hide_dropped_branches();
  }

  Result<EffectFile> parse() {
    out_.path = path_;
    std::size_t i = 0;
    while (i < tokens_.size()) {
      if (tokens_[i].kind == TokenKind::directive) {
        ++i;
        continue;
      }
      auto item = next_item(i);
      if (!item) return std::unexpected(item.error());
      if (auto ok = classify(*item); !ok) return std::unexpected(ok.error());
      i = item->end;
    }
    resolve_sampler_types();
    out_.hlsl = cg::rebuild(text_, tokens_);
    return std::move(out_);
  }

 private:
  // What an #if drops is not this effect's (EffectConditionals.h): the layer reads those
  // tokens as it reads directives, not at all, and leaves them in the text for glslang's
  // preprocessor to drop.
  void hide_dropped_branches() {
    ConditionalRegions regions = conditional_regions(tokens_);
    for (std::size_t k = 0; k < tokens_.size(); ++k)
      if (!regions.active[k]) tokens_[k].kind = TokenKind::directive;
    for (EffectNote& note : regions.notes) out_.notes.push_back(std::move(note));
  }

  Error error_at(const Token& t, std::string message) const {
    return Error{.message = std::move(message), .file = path_, .line = t.line, .stage = ErrorStage::compile};
  }
  Error error_at_end(std::string message) const {
    const int line = tokens_.empty() ? 0 : tokens_.back().line;
    return Error{.message = std::move(message), .file = path_, .line = line, .stage = ErrorStage::compile};
  }

  // Finds where the item starting at `i` ends, tracking (), [] and {} nesting.
  Result<Item> next_item(std::size_t i) const {
    Item item{.begin = i};
    const bool block_item = is_technique_keyword(tokens_[i]) || tokens_[i].is("cbuffer") ||
                            tokens_[i].is("tbuffer") || tokens_[i].is("namespace");
    int depth = 0;
    bool saw_paren = false, saw_assign = false;
    for (std::size_t j = i; j < tokens_.size(); ++j) {
      const Token& t = tokens_[j];
      if (t.kind == TokenKind::directive) continue;
      if (t.kind != TokenKind::punctuation) continue;
      // An annotation's `;` and `=` are its own, not the declaration's.
      if (depth == 0 && t.is("<"))
        if (std::size_t close = annotation_end(j, tokens_.size())) {
          j = close - 1;
          continue;
        }
      if (depth == 0 && t.is(";")) {
        item.end = j + 1;
        return item;
      }
      if (depth == 0 && t.is("=")) saw_assign = true;
      if (t.is("(") || t.is("[") || t.is("{")) {
        if (depth == 0 && t.is("(")) saw_paren = true;
        if (depth == 0 && t.is("{") && !saw_assign && (saw_paren || block_item) && !item.has_body) {
          item.has_body = true;
          item.body_open = j;
        }
        ++depth;
      } else if (t.is(")") || t.is("]") || t.is("}")) {
        if (--depth < 0) return std::unexpected(error_at(t, "unbalanced '" + t.text + "'"));
        if (depth == 0 && t.is("}") && item.has_body) {
          // A body ends the item; a `;` right after it belongs to it.
          std::size_t k = j + 1;
          while (k < tokens_.size() && tokens_[k].kind == TokenKind::directive) ++k;
          item.end = (k < tokens_.size() && tokens_[k].is(";")) ? k + 1 : j + 1;
          return item;
        }
      }
    }
    return std::unexpected(error_at_end("unexpected end of file (a missing ';' or '}' after line " +
                                        std::to_string(tokens_[i].line) + ")"));
  }

  void remove(std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      if (tokens_[k].kind != TokenKind::directive) tokens_[k].removed = true;
  }

  // The index after the `>` closing an annotation opened at `open`, or 0 if `open` does
  // not start one. Annotations follow a name or semantic: `< string UIName = "x"; >`;
  // a template argument (`Texture2D<float4>`) is not one.
  std::size_t annotation_end(std::size_t open, std::size_t limit) const {
    if (open == 0 || !tokens_[open].is("<") || !tokens_[open - 1].is_identifier()) return 0;
    const std::size_t a = open + 1;
    if (a >= limit) return 0;
    const bool empty = tokens_[a].is(">");
    const bool declaration = a + 1 < limit && tokens_[a].is_identifier() && tokens_[a + 1].is_identifier();
    if (!empty && !declaration) return 0;
    for (std::size_t k = a; k < limit; ++k)
      if (tokens_[k].is(">")) return k + 1;
    return 0;
  }

  // Removes every annotation in [begin, end) at depth 0 of the item.
  void remove_annotations(std::size_t begin, std::size_t end) {
    int depth = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const Token& t = tokens_[k];
      if (t.is("(") || t.is("[") || t.is("{")) ++depth;
      if (t.is(")") || t.is("]") || t.is("}")) --depth;
      if (depth != 0) continue;
      if (std::size_t close = annotation_end(k, end)) {
        remove(k, close);
        k = close - 1;
      }
    }
  }

  std::size_t first_after_qualifiers(const Item& item) const {
    std::size_t k = item.begin;
    while (k < item.end && is_storage_qualifier(tokens_[k])) ++k;
    return k;
  }

  Result<void> classify(const Item& item) {
    const Token& first = tokens_[item.begin];
    if (is_technique_keyword(first)) return parse_technique(item);
    const std::size_t type_at = first_after_qualifiers(item);
    if (type_at >= item.end) return {};
    const Token& type = tokens_[type_at];
    for (std::size_t k = item.begin; k < item.end; ++k)
      if (tokens_[k].is("sampler_state")) return parse_sampler(item, type_at);
    if (type.is("VertexShader") || type.is("PixelShader") || type.is("vertexshader") || type.is("pixelshader") ||
        type.is("asm"))
      return std::unexpected(error_at(type, "effect feature '" + type.text +
                                                " variable' is not supported by shaderbed's effect layer (write the "
                                                "`compile` statement in the pass)"));
    if (type.is("stateblock") || type.is("BlendState") || type.is("DepthStencilState") ||
        type.is("RasterizerState") || type.is("fxgroup"))
      return std::unexpected(error_at(type, "effect feature '" + type.text +
                                                "' is not supported by shaderbed's effect layer (state objects; set "
                                                "the states in the pass)"));
    if (is_dx9_texture_type(type) && !item.has_body) {
      if (type_at + 1 >= item.end || !tokens_[type_at + 1].is_identifier())
        return std::unexpected(error_at(type, "expected a name after '" + type.text + "'"));
      out_.textures.push_back({tokens_[type_at + 1].text, type.text, type.line});
      out_.notes.push_back({type.line, "texture '" + tokens_[type_at + 1].text +
                                           "' declaration removed: a case binds it by this name or by the sampler that names it"});
      remove(item.begin, item.end);
      return {};
    }
    if (type.is("string") && !item.has_body) {
      out_.notes.push_back({type.line, "string global removed: HLSL for SPIR-V has no strings"});
      remove(item.begin, item.end);
      return {};
    }
    for (std::size_t k = item.begin; k < type_at; ++k)
      if (tokens_[k].is("shared")) tokens_[k].removed = true;  // one effect pool: meaningless here
    if (item.has_body && !first.is("cbuffer") && !first.is("tbuffer") && !first.is("namespace")) {
      record_function(item, type_at);
      return {};
    }
    remove_annotations(item.begin, item.has_body ? item.body_open : item.end);
    if (item.has_body) remove_annotations(item.body_open, item.end);  // cbuffer members
    if (!item.has_body) record_initial_value(item, type_at);
    return {};
  }

  // `type name [: semantic] = value;` of a global the application can set (not static
  // or const), with a value of numbers: `0.5f`, `{0.04, 0.04, 0.04}`, `float3(1, 0, 0)`.
  void record_initial_value(const Item& item, std::size_t type_at) {
    for (std::size_t k = item.begin; k < type_at; ++k)
      if (tokens_[k].is("static") || tokens_[k].is("const")) return;
    const int components = numeric_components(tokens_[type_at].text);
    if (components == 0 || type_at + 1 >= item.end || !tokens_[type_at + 1].is_identifier()) return;
    std::vector<const Token*> rest;   // what follows the name, annotations and other hidden tokens left out
    for (std::size_t k = type_at + 2; k < item.end; ++k)
      if (!tokens_[k].removed && tokens_[k].kind != TokenKind::directive) rest.push_back(&tokens_[k]);
    auto assign = std::ranges::find_if(rest, [](const Token* t) { return t->is("=") || t->is("[") || t->is(","); });
    if (assign == rest.end() || !(*assign)->is("=")) return;   // no value, an array, or several names
    std::vector<const Token*> value(assign + 1, rest.end());
    if (!value.empty() && value.back()->is(";")) value.pop_back();
    // Unwrap `{ ... }` or `floatN( ... )`.
    if (value.size() >= 2 && value.front()->is("{") && value.back()->is("}")) {
      value = {value.begin() + 1, value.end() - 1};
    } else if (value.size() >= 3 && value.front()->is_identifier() && value[1]->is("(") && value.back()->is(")")) {
      if (numeric_components(value.front()->text) != components) return;
      value = {value.begin() + 2, value.end() - 1};
    }
    EffectInitialValue initial{.line = tokens_[type_at + 1].line};
    std::string element;
    for (std::size_t k = 0; k <= value.size(); ++k) {
      if (k < value.size() && !value[k]->is(",")) {
        element += value[k]->text;
        continue;
      }
      const std::optional<double> v = initial_number(element);
      if (!v) return;   // an expression: not something to read without a compiler
      initial.values.push_back(*v);
      element.clear();
    }
    if (initial.values.size() == 1 && components > 1) initial.values.assign(std::size_t(components), initial.values[0]);
    if (initial.values.size() != std::size_t(components)) return;
    out_.initial_values[tokens_[type_at + 1].text] = std::move(initial);
  }

  void record_function(const Item& item, std::size_t type_at) {
    std::size_t open = type_at;
    while (open < item.body_open && !tokens_[open].is("(")) ++open;
    if (open == type_at || open >= item.body_open) return;
    EffectFunction f;
    f.name = tokens_[open - 1].text;
    f.line = tokens_[open - 1].line;
    for (std::size_t k = type_at; k + 1 < open; ++k) f.return_type += (f.return_type.empty() ? "" : " ") + tokens_[k].text;
    // Parameters: split at depth-1 commas up to the matching ')'.
    int depth = 0;
    std::size_t close = open;
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    std::size_t start = open + 1;
    for (std::size_t k = open; k < item.body_open; ++k) {
      const Token& t = tokens_[k];
      if (t.is("(") || t.is("[") || t.is("{")) ++depth;
      if (t.is(")") || t.is("]") || t.is("}")) {
        if (--depth == 0) {
          close = k;
          if (k > start) ranges.push_back({start, k});
          break;
        }
      }
      if (depth == 1 && t.is(",")) {
        ranges.push_back({start, k});
        start = k + 1;
      }
    }
    for (auto [b, e] : ranges) {
      EffectParameter p;
      std::size_t name_end = e;
      for (std::size_t k = b; k < e; ++k) {
        if (tokens_[k].is(":") || tokens_[k].is("=")) {
          name_end = std::min(name_end, k);
          if (tokens_[k].is("=")) {
            for (std::size_t d = k + 1; d < e; ++d) p.default_value += (p.default_value.empty() ? "" : " ") + tokens_[d].text;
            e = k;
            break;
          }
        }
      }
      for (std::size_t k = b; k < e; ++k) p.text += (p.text.empty() ? "" : " ") + tokens_[k].text;
      for (std::size_t k = b; k < name_end; ++k) {
        if (tokens_[k].is("uniform")) p.is_uniform = true;
        if (tokens_[k].is_identifier()) p.name = tokens_[k].text;
        if (tokens_[k].is("[")) break;
      }
      if (p.text == "void") continue;
      f.parameters.push_back(std::move(p));
    }
    for (std::size_t k = close + 1; k < item.body_open; ++k)
      if (tokens_[k].is(":"))
        for (std::size_t s = k + 1; s < item.body_open; ++s)
          f.return_semantic += tokens_[s].text;
    out_.functions.push_back(std::move(f));
  }

  // `sampler2D s [: register(s0)] [<...>] = sampler_state { State = value; ... };`
  Result<void> parse_sampler(const Item& item, std::size_t type_at) {
    const Token& type = tokens_[type_at];
    if (!is_effect_sampler_type(type.text))
      return std::unexpected(error_at(type, "effect feature 'sampler_state' on a '" + type.text +
                                                "' is not supported by shaderbed's effect layer (declare a sampler, "
                                                "sampler2D, sampler3D or samplerCUBE)"));
    if (type_at + 1 >= item.end || !tokens_[type_at + 1].is_identifier())
      return std::unexpected(error_at(type, "expected a sampler name after '" + type.text + "'"));
    EffectSampler sampler{.name = tokens_[type_at + 1].text, .type = type.text, .line = type.line};
    std::size_t assign = type_at + 2;
    while (assign < item.end && !tokens_[assign].is("=")) ++assign;
    std::size_t open = assign + 1;
    if (open + 1 >= item.end || !tokens_[open].is("sampler_state") || !tokens_[open + 1].is("{"))
      return std::unexpected(error_at(type, "expected '= sampler_state { ... }' for sampler '" + sampler.name + "'"));
    remove_annotations(type_at, assign);
    auto states = parse_assignments(open + 2);
    if (!states) return std::unexpected(states.error());
    for (const EffectAssignment& state : states->first)
      if (auto ok = apply_sampler_state(state, sampler, path_, out_.notes); !ok) return ok;
    // The block goes; `sampler2D s : register(s0);` stays for glslang.
    remove(assign, states->second);
    pending_samplers_.push_back(out_.samplers.size());
    samplers_type_token_.push_back(type_at);
    out_.samplers.push_back(std::move(sampler));
    return {};
  }

  // `Name [ [index] ] = value ;` or `Name ( value ) ;` up to the `}` closing the block
  // whose contents start at `i`. Returns the assignments and the index after that `}`.
  Result<std::pair<std::vector<EffectAssignment>, std::size_t>> parse_assignments(std::size_t i) const {
    std::vector<EffectAssignment> out;
    while (i < tokens_.size()) {
      const Token& t = tokens_[i];
      if (t.kind == TokenKind::directive) {
        ++i;
        continue;
      }
      if (t.is("}")) return std::pair{std::move(out), i + 1};
      if (t.is(";")) {
        ++i;
        continue;
      }
      if (!t.is_identifier()) return std::unexpected(error_at(t, "expected a state name, found '" + t.text + "'"));
      EffectAssignment a{.name = t.text, .line = t.line};
      std::size_t k = i + 1;
      if (k < tokens_.size() && tokens_[k].is("[")) {
        if (k + 2 >= tokens_.size() || tokens_[k + 2].text != "]")
          return std::unexpected(error_at(t, "expected 'State[index]' for state '" + t.text + "'"));
        try {
          a.index = std::stoi(tokens_[k + 1].text);
        } catch (...) {
          return std::unexpected(error_at(t, "state '" + t.text + "' has a non-numeric index '" +
                                                 tokens_[k + 1].text + "'"));
        }
        k += 3;
      }
      bool call = false;  // SM4 style: SetVertexShader( ... );
      if (k < tokens_.size() && tokens_[k].is("(")) {
        call = true;
      } else if (k >= tokens_.size() || !tokens_[k].is("=")) {
        return std::unexpected(error_at(t, "expected '=' after state '" + t.text + "'"));
      } else {
        ++k;
      }
      int depth = 0;
      std::size_t v = k;
      for (; v < tokens_.size(); ++v) {
        const Token& x = tokens_[v];
        if (x.kind == TokenKind::directive) continue;
        if (depth == 0 && (x.is(";") || x.is("}"))) break;
        if (x.is("(") || x.is("[") || x.is("{")) ++depth;
        if (x.is(")") || x.is("]") || x.is("}")) --depth;
        a.value_tokens.push_back(x.text);
      }
      if (v >= tokens_.size() || !tokens_[v].is(";"))
        return std::unexpected(error_at(t, "expected ';' after state '" + t.text + "'"));
      if (call && a.value_tokens.size() >= 2) {  // drop the call's own parentheses
        a.value_tokens.erase(a.value_tokens.begin());
        a.value_tokens.pop_back();
      }
      for (const std::string& s : a.value_tokens) a.value += (a.value.empty() ? "" : " ") + s;
      if (a.value_tokens.empty()) return std::unexpected(error_at(t, "state '" + t.text + "' has no value"));
      out.push_back(std::move(a));
      i = v + 1;
    }
    return std::unexpected(error_at_end("unexpected end of file inside a state block"));
  }

  // Skips `[name] [<annotation>]` starting at `i`; returns the name and the next index.
  std::pair<std::string, std::size_t> name_and_annotation(std::size_t i, std::size_t limit) const {
    std::string name;
    if (i < limit && tokens_[i].is_identifier()) name = tokens_[i++].text;
    if (i < limit && tokens_[i].is("<"))
      for (std::size_t k = i; k < limit; ++k)
        if (tokens_[k].is(">")) return {name, k + 1};
    return {name, i};
  }

  Result<void> parse_technique(const Item& item) {
    EffectTechnique technique{.line = tokens_[item.begin].line};
    auto [name, i] = name_and_annotation(item.begin + 1, item.end);
    technique.name = name;
    if (i >= item.end || !tokens_[i].is("{"))
      return std::unexpected(error_at(tokens_[item.begin], "expected '{' after technique '" + name + "'"));
    ++i;
    while (i < item.end && !tokens_[i].is("}")) {
      const Token& t = tokens_[i];
      if (t.kind == TokenKind::directive) {
        ++i;
        continue;
      }
      if (!t.is("pass"))
        return std::unexpected(error_at(t, "expected 'pass' in technique '" + technique.name + "', found '" +
                                               t.text + "'"));
      EffectPass pass{.line = t.line};
      auto [pass_name, at] = name_and_annotation(i + 1, item.end);
      pass.name = pass_name;
      if (at >= item.end || !tokens_[at].is("{"))
        return std::unexpected(error_at(t, "expected '{' after pass '" + pass.name + "'"));
      auto states = parse_assignments(at + 1);
      if (!states) return std::unexpected(states.error());
      pass.states = std::move(states->first);
      technique.passes.push_back(std::move(pass));
      i = states->second;
    }
    if (technique.passes.empty())
      return std::unexpected(error_at(tokens_[item.begin], "technique '" + technique.name + "' has no pass"));
    out_.techniques.push_back(std::move(technique));
    remove(item.begin, item.end);
    return {};
  }

  // A generic `sampler` becomes the type its use or its texture says (texCUBE -> samplerCUBE).
  void resolve_sampler_types() {
    for (std::size_t n = 0; n < pending_samplers_.size(); ++n) {
      EffectSampler& s = out_.samplers[pending_samplers_[n]];
      Token& type = tokens_[samplers_type_token_[n]];
      if (s.type == "sampler") {
        std::string texture_type;
        for (const EffectTexture& t : out_.textures)
          if (t.name == s.texture) texture_type = t.type;
        s.type = texture_type == "textureCUBE" ? "samplerCUBE"
                 : texture_type == "texture3D" ? "sampler3D"
                 : texture_type == "texture1D" ? "sampler1D"
                                               : used_as(s.name);
      }
      type.text = s.type;
    }
  }

  std::string used_as(const std::string& sampler) const {
    for (std::size_t k = 0; k + 2 < tokens_.size(); ++k) {
      if (!tokens_[k + 1].is("(") || !tokens_[k + 2].is(sampler)) continue;
      const std::string& f = tokens_[k].text;
      if (f.starts_with("texCUBE")) return "samplerCUBE";
      if (f.starts_with("tex3D")) return "sampler3D";
      if (f.starts_with("tex1D")) return "sampler1D";
    }
    return "sampler2D";
  }

  std::string_view text_;
  std::string path_;
  std::vector<Token> tokens_;
  EffectFile out_;
  std::vector<std::size_t> pending_samplers_;
  std::vector<std::size_t> samplers_type_token_;
};

}  // namespace

const EffectFunction* EffectFile::function(std::string_view name) const {
  for (const EffectFunction& f : functions)
    if (f.name == name) return &f;
  return nullptr;
}

bool is_effect_file(const std::string& path, std::string_view text) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".fx") return true;
  if (text.find("technique") == std::string_view::npos) return false;
  const std::vector<Token> tokens = cg::lex(text);
  for (std::size_t k = 0; k + 1 < tokens.size(); ++k)
    if (is_technique_keyword(tokens[k]) && (tokens[k + 1].is_identifier() || tokens[k + 1].is("{"))) return true;
  return false;
}

Result<EffectFile> parse_effect(std::string_view text, const std::string& path) {
  auto parsed = Parser(text, path).parse();
  if (!parsed) return parsed;
  if (parsed->techniques.empty())
    return std::unexpected(Error{.message = "effect file declares no technique (shaderbed takes a technique's "
                                            "pass for the entry points and states)",
                                 .file = path,
                                 .stage = ErrorStage::compile});
  return parsed;
}

}  // namespace shaderbed
