#include "author/ShaderText.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>

#include "compile/EffectFile.h"
#include "core/AsciiCase.h"

namespace shaderbed {
namespace {

bool identifier(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

std::smatch search(const std::string& text, const std::string& pattern) {
  std::smatch m;
  std::regex_search(text, m, std::regex(pattern));
  return m;
}

// What may stand between a declared name and its semantic: an array size.
const char* kArray = R"((?:\s*\[[^\]]*\])?)";

SpaceHint space_in(const std::string& words) {
  const std::string l = ascii_lower(words);
  for (const char* w : {"world space", "world-space", "\"world\""}) if (l.find(w) != std::string::npos) return SpaceHint::world;
  for (const char* w : {"view space", "view-space", "eye space", "eye-space", "camera space", "\"view\"", "\"eye\""})
    if (l.find(w) != std::string::npos) return SpaceHint::view;
  for (const char* w : {"object space", "object-space", "model space", "\"object\""})
    if (l.find(w) != std::string::npos) return SpaceHint::object;
  return SpaceHint::none;
}

std::string trim(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  return s;
}

// One mul() argument without casts and enclosing parentheses: "(float3x3)g_mWorld" -> "g_mWorld".
std::string bare_argument(std::string a) {
  static const std::regex cast(R"(^\(\s*[A-Za-z_]\w*\s*\)\s*)");
  for (;;) {
    a = trim(a);
    if (std::smatch m; std::regex_search(a, m, cast) && m.length(0) < std::ptrdiff_t(a.size())) {
      a = a.substr(size_t(m.length(0)));
      continue;
    }
    if (a.size() > 2 && a.front() == '(' && a.back() == ')') {
      a = a.substr(1, a.size() - 2);
      continue;
    }
    return a;
  }
}

bool is_position_semantic(const std::string& s) {
  const std::string u = ascii_upper(s);
  return u == "SV_POSITION" || u == "HPOS" || u.starts_with("POSITION");
}

bool is_colour_semantic(const std::string& s) {
  const std::string u = ascii_upper(s);
  return u.starts_with("SV_TARGET") || u.starts_with("COLOR") || u == "COL";
}

// The semantics a struct's members carry, by struct name.
std::map<std::string, std::vector<std::string>> struct_semantics(const std::string& text) {
  std::map<std::string, std::vector<std::string>> out;
  static const std::regex structure(R"(\bstruct\s+([A-Za-z_]\w*)\s*\{([^}]*)\})");
  static const std::regex semantic(R"(:\s*([A-Za-z_]\w*)\s*;)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), structure); it != std::sregex_iterator(); ++it) {
    const std::string body = (*it)[2];
    auto& list = out[(*it)[1]];
    for (auto s = std::sregex_iterator(body.begin(), body.end(), semantic); s != std::sregex_iterator(); ++s)
      list.push_back((*s)[1]);
  }
  return out;
}

}  // namespace

std::string declared_semantic(std::string_view view, std::string_view name) {
  if (!identifier(name)) return "";
  const std::string text(view);
  const auto m = search(text, R"(\b[A-Za-z_]\w*\s+)" + std::string(name) + kArray + R"(\s*:\s*([A-Za-z_]\w*)\s*[;<=,):])");
  if (m.empty()) return "";
  const std::string s = m[1];
  return s == "register" || s == "packoffset" ? "" : s;
}

int declared_register(std::string_view view, std::string_view name) {
  if (!identifier(name)) return -1;
  const std::string text(view);
  const auto m = search(text, R"(\b)" + std::string(name) + kArray +
                                  R"(\s*(?::\s*[A-Za-z_]\w*\s*)?:\s*register\s*\(\s*c(\d+)\s*\))");
  return m.empty() ? -1 : std::stoi(m[1]);
}

namespace {

// The declaration of `name` up to its end (';', or ',' / ')' in a parameter list), plus the
// rest of that line: its annotation and its trailing comment. "" when there is none.
std::string declaration_of(const std::string& text, std::string_view name) {
  if (!identifier(name)) return "";
  const auto m = search(text, R"(\b[A-Za-z_]\w*\s+)" + std::string(name) + kArray + R"(\s*[:;=,<)])");
  if (m.empty()) return "";
  const size_t begin = size_t(m.position(0));
  size_t end = text.find_first_of(";,)", begin + size_t(m.length(0)) - 1);
  if (end == std::string::npos) end = text.size();
  // An annotation block holds ';' of its own: read on to the block's end.
  if (const size_t open = text.find('<', begin); open != std::string::npos && open < end) {
    const size_t close = text.find('>', open);
    if (close != std::string::npos) end = text.find(';', close);
    if (end == std::string::npos) end = text.size();
  }
  size_t line_end = text.find('\n', end);
  if (line_end == std::string::npos) line_end = text.size();
  return text.substr(begin, line_end - begin);
}

// The declaration's trailing comment, without the "//"; "" when it has none.
std::string comment_of(const std::string& declaration) {
  const size_t comment = declaration.find("//");
  return comment == std::string::npos ? "" : declaration.substr(comment + 2);
}

}  // namespace

SpaceHint declared_space(std::string_view view, std::string_view name) {
  const std::string declaration = declaration_of(std::string(view), name);
  if (declaration.empty()) return SpaceHint::none;
  if (const auto a = search(declaration, R"(\bSpace\s*=\s*"(\w+)\")"); !a.empty()) return space_in("\"" + std::string(a[1]) + "\"");
  const std::string comment = comment_of(declaration);
  return comment.empty() ? SpaceHint::none : space_in(comment);
}

std::vector<std::pair<std::string, std::string>> component_meanings(std::string_view view, std::string_view name) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::string comment = comment_of(declaration_of(std::string(view), name));
  // "rgb = colour, w = specular power"; "xyz: direction; w: 0 for directional".
  static const std::regex piece(R"(^\s*\.?([xyzw]{1,4}|[rgba]{1,4})\s*[=:]\s*(.*\S)\s*$)");
  size_t begin = 0;
  while (begin <= comment.size()) {
    size_t end = comment.find_first_of(",;", begin);
    if (end == std::string::npos) end = comment.size();
    const std::string part = comment.substr(begin, end - begin);
    if (std::smatch m; std::regex_match(part, m, piece)) out.emplace_back(m[1], m[2]);
    begin = end + 1;
  }
  return out;
}

std::optional<MatrixLayout> mul_order(std::string_view view, std::string_view name) {
  const std::string text(view);
  static const std::regex call(R"(\bmul\s*\()");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
    size_t k = size_t(it->position(0) + it->length(0));
    int depth = 1;
    std::vector<std::string> args(1);
    for (; k < text.size() && depth > 0; ++k) {
      const char c = text[k];
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (depth == 0) break;
      if (depth == 1 && c == ',') args.emplace_back();
      else args.back() += c;
    }
    if (args.size() != 2) continue;
    if (bare_argument(args[0]) == name) return MatrixLayout::column_vector;
    if (bare_argument(args[1]) == name) return MatrixLayout::row_vector;
  }
  return std::nullopt;
}

Stage glsl_stage_of(std::string_view text) {
  return std::regex_search(std::string(text), std::regex(R"(\bgl_Position\b)")) ? Stage::vertex : Stage::fragment;
}

Result<std::vector<EntryCandidate>> entry_candidates(std::string_view view, const std::string& path) {
  const std::string text(view);
  // The effect parser lists a file's functions with their signatures; it wants a
  // technique, so a plain HLSL/Cg file gets an empty one after its last line.
  const bool effect_file = is_effect_file(path, text);
  auto effect = parse_effect(effect_file ? text : text + "\ntechnique shaderbed_init_functions { pass {} }\n", path);
  if (!effect) return std::unexpected(effect.error());
  const auto structs = struct_semantics(text);
  std::vector<EntryCandidate> out;
  for (const EffectFunction& f : effect->functions) {
    std::vector<std::string> outputs;
    const auto add_type = [&](const std::string& type) {
      if (auto s = structs.find(type); s != structs.end()) outputs.insert(outputs.end(), s->second.begin(), s->second.end());
    };
    if (!f.return_semantic.empty()) outputs.push_back(f.return_semantic);
    add_type(f.return_type);
    for (const EffectParameter& p : f.parameters) {
      std::vector<std::string> words;
      std::string word;
      for (char c : p.text + " ") {
        if (std::isspace(static_cast<unsigned char>(c))) {
          if (!word.empty()) words.push_back(word);
          word.clear();
        } else {
          word += c;
        }
      }
      if (words.empty() || (words[0] != "out" && words[0] != "inout")) continue;
      if (words.size() > 1) add_type(words[1]);
      for (size_t i = 0; i + 1 < words.size(); ++i)
        if (words[i] == ":") outputs.push_back(words[i + 1]);
    }
    if (std::any_of(outputs.begin(), outputs.end(), is_position_semantic))
      out.push_back({f.name, Stage::vertex, f.line});
    else if (std::any_of(outputs.begin(), outputs.end(), is_colour_semantic))
      out.push_back({f.name, Stage::fragment, f.line});
  }
  return out;
}

}  // namespace shaderbed
