#include "author/BindingGuess.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>

#include "compile/LegacyGlsl.h"
#include "core/AsciiCase.h"

namespace shaderbed {
namespace {

using Words = std::vector<std::string>;

bool is_upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }
bool is_lower(char c) { return std::islower(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

// Words authors glue together ("modelview", "lightdir", "WORLDVIEWPROJECTION").
constexpr std::array kVocabulary = {
    "world",    "model",     "object",     "obj",      "local",     "view",     "camera",    "cam",
    "eye",      "viewer",    "proj",       "projection", "persp",   "perspective", "wvp",   "mvp",
    "wv",       "mv",        "vp",         "transform", "xform",    "inverse",  "inv",       "transpose",
    "trans",    "it",        "normal",     "matrix",   "mat",       "mtx",      "light",     "dir",
    "direction", "vec",      "vector",     "pos",      "position",  "location", "loc",       "origin",
    "to",       "sun",       "ambient",    "diffuse",  "specular",  "spec",     "power",     "exponent",
    "shininess", "gloss",    "glossiness", "color",    "colour",    "col",      "emissive",  "emission",
    "material", "base",      "albedo",     "surface",  "global",    "padding",  "pad",       "intensity",
    "space",    "ws",        "vs",         "es",       "os",        "ec",       "scale",     "factor",
    "debug",    "multiplier", "unity"};

bool in_vocabulary(std::string_view w) {
  return std::find(kVocabulary.begin(), kVocabulary.end(), w) != kVocabulary.end();
}

// A glued word split into the fewest vocabulary words that cover it exactly; the word
// itself when no cover exists.
Words split_glued(const std::string& word) {
  if (in_vocabulary(word) || word.size() < 4) return {word};
  const size_t n = word.size();
  std::vector<int> parts(n + 1, 1 << 20);
  std::vector<size_t> from(n + 1, 0);
  parts[0] = 0;
  for (size_t end = 1; end <= n; ++end)
    for (size_t begin = 0; begin < end; ++begin)
      if (parts[begin] + 1 < parts[end] && in_vocabulary(std::string_view(word).substr(begin, end - begin))) {
        parts[end] = parts[begin] + 1;
        from[end] = begin;
      }
  if (parts[n] >= (1 << 20)) return {word};
  Words out;
  for (size_t end = n; end > 0; end = from[end]) out.insert(out.begin(), word.substr(from[end], end - from[end]));
  return out;
}

bool has(const Words& w, std::string_view word) { return std::find(w.begin(), w.end(), word) != w.end(); }
bool has_any(const Words& w, std::initializer_list<std::string_view> words) {
  return std::any_of(words.begin(), words.end(), [&](std::string_view x) { return has(w, x); });
}

std::vector<double> zeros(size_t n) { return std::vector<double>(n, 0.0); }

size_t value_count(const UniformFacts& u) {
  return size_t(u.vecsize) * u.columns * (u.array_size ? u.array_size : 1);
}

BindingSource named(std::string name) { return BindingSource{.name = std::move(name), .literal = {}}; }
BindingSource literal(std::vector<double> v) { return BindingSource{.name = "", .literal = std::move(v)}; }

UniformGuess guessed(std::vector<BindingSource> sources, std::string reason) {
  return UniformGuess{.sources = std::move(sources), .reason = std::move(reason)};
}

// --- matrices -------------------------------------------------------------------------

// What the words of a matrix's name say it is, e.g. {world, view, proj} -> "transform",
// {normal} (3x3) -> "normal_matrix"; "" when a word is not a matrix word.
std::string matrix_quantity(const Words& words, const UniformFacts& u, std::string& what) {
  bool world = false, view = false, proj = false, inverse = false, transpose = false, normal = false;
  bool transform = false;
  const bool glued_name = words.size() == 1;
  // Unity's "from to" names: unity_ObjectToWorld is the world matrix, unity_WorldToObject its inverse.
  if (const auto to = std::find(words.begin(), words.end(), "to"); to != words.end() && to + 1 != words.end()) {
    const auto object_space = [](const std::string& w) { return w == "object" || w == "obj" || w == "model" || w == "local"; };
    if (std::any_of(words.begin(), to, object_space) && *(to + 1) == "world") return what = "the world (model) matrix", "world";
    if (to != words.begin() && *(to - 1) == "world" && std::any_of(to + 1, words.end(), object_space))
      return what = "the world (model) matrix, inverted", "world_inverse";
    return "";
  }
  for (const std::string& w : words) {
    if (w == "matrix" || w == "mat" || w == "mtx" || w == "unity" || std::all_of(w.begin(), w.end(), is_digit)) continue;
    if (w == "world" || w == "model" || w == "object" || w == "obj" || w == "local") world = true;
    else if (w == "view" || w == "camera" || w == "cam" || w == "eye") view = true;
    else if (w == "proj" || w == "projection" || w == "persp" || w == "perspective") proj = true;
    else if (w == "wvp" || w == "mvp") world = view = proj = true;
    else if (w == "wv" || w == "mv") world = view = true;
    else if (w == "vp") view = proj = true;
    else if (w == "transform" || w == "xform" || (w == "trans" && glued_name)) transform = true;
    else if (w == "inverse" || w == "inv") inverse = true;
    else if (w == "transpose" || w == "trans") transpose = true;
    else if (w == "it") inverse = transpose = true;
    else if (w == "normal") normal = true;
    else return "";
  }
  const bool square3 = u.columns == 3 && u.vecsize == 3;
  if (normal) {
    if (proj) return "";
    what = "the normal matrix";
    if (square3) return view ? "normal_matrix_view" : "normal_matrix";
    what += " (a 4x4: the world matrix's inverse transpose)";
    return view ? "world_view_inverse_transpose" : "world_inverse_transpose";
  }
  if (transform && !world && !view && !proj) world = view = proj = true;
  std::string base;
  if (world && view && proj) base = "transform", what = "world-view-projection";
  else if (world && view) base = "world_view", what = "world-view (model-view)";
  else if (view && proj) base = "view_projection", what = "view-projection";
  else if (world && !proj) base = "world", what = "the world (model) matrix";
  else if (view && !world) base = "view", what = "the view matrix";
  else if (proj && !world) base = "projection", what = "the projection matrix";
  else return "";
  if (inverse && transpose) base += "_inverse_transpose", what += ", inverse transposed";
  else if (inverse) base += "_inverse", what += ", inverted";
  else if (transpose) base += "_transpose", what += ", transposed";
  return base;
}

// Effect (SAS) semantics name the matrix glued: WORLDVIEWPROJECTION, WORLDINVERSETRANSPOSE.
std::string matrix_from_semantic(const UniformFacts& u, std::string& what) {
  if (u.semantic.empty()) return "";
  return matrix_quantity(split_glued(ascii_lower(u.semantic)), u, what);
}

// Book-style registers (docs/cases.md, "The scene"): c0 transform, c4 light vector, c5 eye, c6 light position.
std::string register_quantity(int reg, std::string& what) {
  switch (reg) {
    case 0: what = "the book's transform slot"; return "transform";
    case 4: what = "the book's light vector slot"; return "light_vector";
    case 5: what = "the book's eye position slot"; return "eye_position";
    case 6: what = "the book's light position slot"; return "light_position";
    default: return "";
  }
}

UniformGuess matrix_guess(std::string quantity, std::string reason, const UniformFacts& u, const GuessContext& c) {
  UniformGuess g = guessed({named(quantity)}, std::move(reason));
  if (c.language == Language::glsl) return g;
  if (u.mul_order == MatrixLayout::row_vector) {
    g.layout = MatrixLayout::row_vector;
    g.reason += "; the source writes mul(v, " + u.name + "): row vectors";
  } else if (!u.mul_order) {
    UniformGuess rows = g;
    rows.layout = MatrixLayout::row_vector;
    rows.reason += "; no mul() names it: row vectors, mul(v, M)";
    g.reason += "; no mul() names it, so column vectors are assumed (for mul(v, M) add layout = \"row_vector\")";
    g.doubt = "column vectors (no mul() names it)";
    g.doubt_group = "matrices";
    g.alternatives.push_back(std::move(rows));
  }
  return g;
}

// --- lighting vectors -----------------------------------------------------------------

enum class Vector { none, light_vector, light_position, eye_position };

Vector vector_kind(const Words& w, std::string& what) {
  const bool light = has_any(w, {"light", "sun"});
  const bool direction = has_any(w, {"dir", "direction", "vec", "vector"});
  const bool position = has_any(w, {"pos", "position", "location", "loc", "origin"});
  if (light && direction) return what = "a direction toward the light", Vector::light_vector;
  if (light && position) return what = "the light's position", Vector::light_position;
  if (has_any(w, {"eye", "camera", "cam", "view", "viewer"}) && (position || w.size() == 1))
    return what = "the eye (camera) position", Vector::eye_position;
  return Vector::none;
}

Vector vector_from_semantic(const UniformFacts& u, std::string& what) {
  const std::string s = ascii_lower(u.semantic);
  if (s.empty()) return Vector::none;
  if (s == "direction" || s == "lightdirection" || s == "lightdir")
    return what = "a light direction", Vector::light_vector;
  if (s == "lightposition" || s == "position") return what = "a light position", Vector::light_position;
  if (s == "cameraposition" || s == "viewposition" || s == "eyeposition" || s == "viewerposition")
    return what = "the camera position", Vector::eye_position;
  return Vector::none;
}

// The space suffix of a lighting quantity and why.
std::string space_suffix(const Words& w, const UniformFacts& u, const GuessContext& c, std::string& why) {
  if (u.name.starts_with("gl_LightSource")) {
    why = "GL keeps its lights in eye (view) space";
    return "_view";
  }
  SpaceHint hint = u.declared_space;
  if (hint != SpaceHint::none) {
    why = "its declaration says " + std::string(hint == SpaceHint::world ? "world" : hint == SpaceHint::view ? "view" : "object") + " space";
  } else if (has_any(w, {"world", "ws"})) {
    hint = SpaceHint::world, why = "its name says world space";
  } else if (has_any(w, {"es", "ec", "vs"}) || (has(w, "eye") && has(w, "light")) ||
             (has(w, "view") && has(w, "light"))) {
    hint = SpaceHint::view, why = "its name says view (eye) space";
  } else if (has_any(w, {"object", "obj", "os", "local", "model"})) {
    hint = SpaceHint::object, why = "its name says object space";
  } else if (c.has_world_matrix) {
    hint = SpaceHint::world, why = "the shader has a world matrix, so it likely lights in world space";
  } else {
    why = "object space, as the book's shaders light (the scene's world matrix is the identity, so = world space)";
  }
  return hint == SpaceHint::world ? "_world" : hint == SpaceHint::view ? "_view" : "";
}

UniformGuess vector_guess(Vector kind, std::string reason, const Words& w, const UniformFacts& u,
                          const GuessContext& c) {
  const char* base = kind == Vector::light_vector ? "light_vector" : kind == Vector::light_position ? "light_position" : "eye_position";
  std::string why;
  const std::string suffix = space_suffix(w, u, c, why);
  reason += "; " + why;
  if (kind == Vector::light_vector) reason += " (check the sign: some shaders take the direction the light travels)";
  UniformGuess g = guessed({named(base + suffix)}, std::move(reason));
  // A float4 light names a position (w = 1) or a direction (w = 0) by its w alone, and
  // shaders written for both (Unity's) test w: the name cannot settle which one it is.
  const bool four = u.vecsize == 4 && !u.name.starts_with("gl_LightSource");
  if (four && kind == Vector::light_position) {
    g.doubt = "a position (w = 1), not a direction";
    g.alternatives.push_back(guessed({named("light_vector" + suffix)}, g.reason + "; taken as a direction toward the light (w = 0)"));
  } else if (four && kind == Vector::light_vector) {
    g.doubt = "a direction (w = 0), not a position";
    g.alternatives.push_back(guessed({named("light_position" + suffix)}, g.reason + "; taken as the light's position (w = 1)"));
  }
  return g;
}

// --- colours and material -------------------------------------------------------------

ParameterGuess parameter(const std::string& name) {
  if (name == "diffuse") return {name, {0.7, 0.5, 0.3}, "a guess: the surface's diffuse colour"};
  if (name == "specular") return {name, {0.3, 0.3, 0.3}, "a guess: the surface's specular colour"};
  return {name, {12.0}, "a guess: the specular exponent"};
}

// What the declaration's comment says one component means ("w = specular power"), "" when it does not.
std::string meaning_of(const UniformFacts& u, std::initializer_list<std::string_view> components) {
  for (const auto& [which, meaning] : u.component_meanings)
    if (std::find(components.begin(), components.end(), which) != components.end()) return meaning;
  return "";
}

bool names_exponent(const Words& w) {
  return has_any(w, {"power", "exponent", "exp", "shininess", "gloss", "glossiness", "smoothness"});
}

// A colour parameter. A 4-vector's w is what its comment says (`// w = specular power`),
// else alpha 1; a specular colour's w without a comment is a doubt, since packing the
// exponent there is common.
UniformGuess colour_guess(const std::string& param, const UniformFacts& u, std::string reason) {
  UniformGuess g = guessed({named(param)}, std::move(reason));
  g.parameters.push_back(parameter(param));
  if (u.vecsize != 4) return g;
  if (const std::string w = meaning_of(u, {"w", "a", ".w", ".a"}); !w.empty()) {
    const Words words = name_words(w);
    g.reason += "; its comment says w = " + w;
    if (names_exponent(words)) {
      g.sources.push_back(named("power"));
      g.parameters.push_back(parameter("power"));
      g.reason += ": the specular exponent";
    } else if (has_any(words, {"unused", "padding", "pad", "0"})) {
      g.sources.push_back(literal({0.0}));
    } else {
      g.sources.push_back(literal({1.0}));
    }
    return g;
  }
  g.sources.push_back(literal({1.0}));
  if (param != "specular") return g;
  UniformGuess power = guessed({named(param), named("power")}, g.reason + "; w taken as the specular exponent");
  power.parameters = {parameter(param), parameter("power")};
  g.doubt = "w = 1 (no comment says what w holds; a specular colour often carries the exponent there)";
  g.alternatives.push_back(std::move(power));
  return g;
}

std::optional<UniformGuess> material_guess(const Words& w, const UniformFacts& u) {
  const std::string& n = u.name;
  const bool vector = !u.columns || u.columns == 1;
  const bool colour = vector && (u.vecsize == 3 || u.vecsize == 4) && !u.array_size;
  const bool scalar = vector && u.vecsize == 1 && !u.array_size;
  const std::string q = "'" + n + "'";
  const auto with_parameter = [&](std::vector<BindingSource> sources, std::string reason, const std::string& param) {
    UniformGuess g = guessed(std::move(sources), std::move(reason));
    g.parameters.push_back(parameter(param));
    return g;
  };
  const bool light = has_any(w, {"light", "sun"});
  const bool material = has_any(w, {"material", "front", "surface", "object"});
  if (has_any(w, {"padding", "pad", "unused", "dummy", "reserved"}))
    return guessed({literal(zeros(value_count(u)))}, "name " + q + " looks like padding");
  // A scale, debug or tuning factor multiplies something the port may not have at all: 1
  // leaves what it scales as it is, whatever else its name says (u_ScaleFGDSpec).
  if (u.is_float && !u.array_size && has_any(w, {"scale", "factor", "multiplier", "debug"}) && !has(w, "power"))
    return guessed({literal(std::vector<double>(value_count(u), 1.0))},
                   "name " + q + " looks like a scale (debug or tuning) factor: 1 leaves what it scales as it is");
  if (has(w, "ambient") && colour) {
    if (material || has(w, "ka") || n.ends_with("Ka"))
      return guessed({literal(std::vector<double>(u.vecsize, 1.0))},
                     "name " + q + " looks like an ambient reflectance: 1 lets the scene's ambient light through");
    if (n.starts_with("gl_LightSource"))
      return guessed({literal(u.vecsize == 4 ? std::vector<double>{0, 0, 0, 1} : zeros(3))},
                     "a GL light's own ambient term: GL's default, none");
    return guessed({named("ambient_light")}, "name " + q + " looks like the ambient light colour");
  }
  const std::string glued = ascii_lower(n);
  if (colour && (has_any(w, {"emissive", "emission"}) || glued == "ke"))
    return guessed({literal(u.vecsize == 4 ? std::vector<double>{0, 0, 0, 1} : zeros(3))},
                   "name " + q + " looks like an emissive colour: none");
  if (colour && glued == "ka")
    return guessed({literal(std::vector<double>(u.vecsize, 1.0))},
                   "name " + q + " looks like an ambient reflectance: 1 lets the scene's ambient light through");
  if (colour && light && has_any(w, {"color", "colour", "col", "diffuse", "specular", "spec", "intensity"}))
    return guessed({literal(std::vector<double>(u.vecsize, 1.0))},
                   "name " + q + " looks like the light's colour: the scene's light is white");
  if (scalar && u.is_float &&
      (has_any(w, {"shininess", "gloss", "glossiness", "exponent"}) ||
       ((has_any(w, {"specular", "spec"}) || w.size() == 1) && has_any(w, {"power", "exp"})) || glued == "ns"))
    return with_parameter({named("power")}, "name " + q + " looks like a specular exponent", "power");
  if (colour && (has_any(w, {"specular", "spec"}) || glued == "ks"))
    return colour_guess("specular", u, "name " + q + " looks like a specular colour");
  if (colour && (has_any(w, {"diffuse", "albedo"}) || glued == "kd" ||
                 (has_any(w, {"color", "colour"}) && (material || has(w, "base")))))
    return colour_guess("diffuse", u, "name " + q + " looks like a diffuse colour");
  // A bare "colour" (Unity's _Color, u_color) is the surface's tint: its diffuse colour.
  if (colour && w.size() == 1 && has_any(w, {"color", "colour"}))
    return colour_guess("diffuse", u, "name " + q + " is a bare colour: the surface's, taken as its diffuse colour");
  return std::nullopt;
}

std::optional<UniformGuess> material_from_semantic(const UniformFacts& u) {
  const std::string s = ascii_lower(u.semantic);
  if (s.empty()) return std::nullopt;
  UniformFacts as_name = u;
  as_name.name = s;
  if (s == "diffuse" || s == "specular" || s == "specularpower" || s == "ambient" || s == "emissive") {
    auto g = material_guess(split_glued(s), as_name);
    if (g) g->reason = "semantic " + u.semantic + (g->reason.substr(g->reason.find(" looks")));
    return g;
  }
  return std::nullopt;
}

std::string todo_text(const UniformFacts& u, const GuessContext& c) {
  return "bind '" + u.name + "' (" + type_text(u, c.language) + "): a case parameter, a scene quantity or a literal";
}

}  // namespace

Words name_words(std::string_view name) {
  Words raw;
  std::string current;
  const auto flush = [&] {
    if (!current.empty()) raw.push_back(ascii_lower(current));
    current.clear();
  };
  for (size_t i = 0; i < name.size(); ++i) {
    const char ch = name[i];
    if (!is_alnum(ch)) {
      flush();
      continue;
    }
    if (!current.empty()) {
      const char prev = current.back();
      const bool lower_to_upper = (is_lower(prev) || is_digit(prev)) && is_upper(ch);
      const bool acronym_end = is_upper(prev) && is_upper(ch) && i + 1 < name.size() && is_lower(name[i + 1]);
      const bool digit_edge = is_digit(prev) != is_digit(ch);
      if (lower_to_upper || acronym_end || digit_edge) flush();
    }
    current += ch;
  }
  flush();
  Words words;
  for (const std::string& w : raw)
    for (std::string& part : split_glued(w)) words.push_back(std::move(part));
  // Scope and Hungarian prefixes: g_, u_, m_, s_, and m/f/v/c before a capital (mWVP, fPower).
  while (words.size() > 1 && words.front().size() == 1 && std::isalpha(static_cast<unsigned char>(words.front()[0])))
    words.erase(words.begin());
  return words;
}

std::string type_text(const UniformFacts& u, Language language) {
  std::string s;
  if (language == Language::glsl) {
    if (u.columns > 1) s = u.columns == u.vecsize ? "mat" + std::to_string(u.columns)
                                                   : "mat" + std::to_string(u.columns) + "x" + std::to_string(u.vecsize);
    else if (u.vecsize > 1) s = std::string(u.is_float ? "vec" : "ivec") + std::to_string(u.vecsize);
    else s = u.is_float ? "float" : "int";
  } else {
    s = u.is_float ? "float" : "int";
    if (u.columns > 1) s += std::to_string(u.vecsize) + "x" + std::to_string(u.columns);
    else if (u.vecsize > 1) s += std::to_string(u.vecsize);
  }
  if (u.array_size) s += "[" + std::to_string(u.array_size) + "]";
  return s;
}

UniformGuess guess_uniform(const UniformFacts& u, const GuessContext& c) {
  if (auto legacy = legacy_glsl_default_binding(u.name)) {
    UniformGuess g;
    g.bound_by_default = true;
    g.reason = "GL's built-in: the scene's " + *legacy + " unless bound here";
    return g;
  }
  const Words w = name_words(u.name);
  const std::string q = "'" + u.name + "'";
  const bool matrix = u.columns > 1 && !u.array_size;
  std::string what;
  if (matrix && u.is_float) {
    if (auto s = matrix_from_semantic(u, what); !s.empty())
      return matrix_guess(s, "semantic " + u.semantic + " is " + what, u, c);
    if (auto s = matrix_quantity(w, u, what); !s.empty())
      return matrix_guess(s, "name " + q + " looks like " + what, u, c);
  }
  const bool vector3or4 = u.columns == 1 && !u.array_size && u.is_float && (u.vecsize == 3 || u.vecsize == 4);
  if (vector3or4) {
    if (auto kind = vector_from_semantic(u, what); kind != Vector::none)
      return vector_guess(kind, "semantic " + u.semantic + " is " + what, w, u, c);
  }
  if (auto g = material_from_semantic(u)) return *g;
  // Unity's forward base pass gives the directional light's direction here, w = 0 (a
  // point light's pass gives its position, w = 1).
  if (vector3or4 && u.vecsize == 4 && u.name.starts_with("_WorldSpaceLightPos"))
    return vector_guess(Vector::light_vector,
                        "Unity's " + q + ": in the forward base pass the direction toward the directional light, w = 0", w, u,
                        c);
  if (vector3or4) {
    if (auto kind = vector_kind(w, what); kind != Vector::none)
      return vector_guess(kind, "name " + q + " looks like " + what, w, u, c);
  }
  if (auto g = material_guess(w, u)) return *g;
  if (u.hlsl_register >= 0 && u.is_float && !u.array_size) {
    if (auto s = register_quantity(u.hlsl_register, what); !s.empty()) {
      const bool fits = s == "transform" ? matrix : vector3or4;
      const std::string reason = "register c" + std::to_string(u.hlsl_register) + " is " + what;
      if (fits && s == "transform") return matrix_guess(s, reason, u, c);
      if (fits) return guessed({named(s)}, reason + " (object space)");
    }
  }
  // A lone int or bool is a switch (`uniform bool halfLambert;`): off draws the shader's
  // plain path; the doubt lets init's check try it on when the run says so.
  if (!u.is_float && u.vecsize == 1 && u.columns == 1 && !u.array_size) {
    UniformGuess off = guessed({BindingSource{.name = "", .literal = {0.0}}},
                               "a guess: " + q + " is a switch (int or bool), off; set 1 (true) for its other path");
    off.doubt = "off or on";
    off.alternatives.push_back(guessed({BindingSource{.name = "", .literal = {1.0}}}, "the switch " + q + " on"));
    return off;
  }
  UniformGuess todo;
  todo.reason = todo_text(u, c);
  todo.placeholder = zeros(value_count(u));
  return todo;
}

std::optional<AttributeGuess> guess_attribute(std::string_view input_name) {
  // Legacy GL inputs (gl_Vertex, ...) are placed by the dialect layer.
  if (input_name.starts_with("gl_")) return std::nullopt;
  Words w = name_words(input_name);
  // in/a/attr/vertex prefixes: aPos, inPosition, a_position, vertexNormal, in_uv.
  std::erase_if(w, [](const std::string& x) { return x == "in" || x == "attr" || x == "attrib" || x == "a"; });
  const std::string q = "'" + std::string(input_name) + "'";
  const auto guess = [&](const char* attribute, const char* what) {
    return AttributeGuess{attribute, "input " + q + " looks like " + what};
  };
  if (w.empty()) return std::nullopt;
  // A packed or encoded attribute travels in some other stream (a colour, a texcoord):
  // only the author knows which.
  if (has_any(w, {"packed", "encoded", "compressed", "quantized", "oct"})) return std::nullopt;
  if (has_any(w, {"normal", "norm", "nrm", "n"})) return guess("normal", "a normal");
  if (has_any(w, {"tangent", "tan"})) return guess("tangent", "a tangent");
  if (has_any(w, {"uv", "texcoord", "texcoords", "tex", "st", "coord", "coords", "uv0", "texcoord0"}) ||
      (has(w, "tex") && has(w, "coord")))
    return guess("texcoord", "a texture coordinate");
  if (has_any(w, {"color", "colour", "col", "rgba", "vc"})) return guess("color", "a vertex colour");
  if (has_any(w, {"pos", "position", "vertex", "vert", "p", "xyz"})) return guess("position", "a position");
  return std::nullopt;
}

}  // namespace shaderbed
