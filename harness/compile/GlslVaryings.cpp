#include "compile/GlslVaryings.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "compile/CgTokens.h"
#include "compile/GlslProfile.h"

namespace shaderbed {
namespace {

// More locations than any GL implementation has (llvmpipe: 32); bounding literals by it
// keeps the location arithmetic below far from int overflow.
constexpr int kMaxLocations = 4096;

// A number token as a non-negative int (decimal, 0x hex, 0 octal; a suffix such as u is
// ignored), or nothing when it is not one (".0", out of range): std::stoi threw there.
std::optional<int> int_literal(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 0);
  if (end == text.c_str() || errno == ERANGE || value < 0 || value > std::numeric_limits<int>::max())
    return std::nullopt;
  return int(value);
}

using cg::Token;
using cg::TokenKind;

bool is_varying_qualifier(const Token& t) {
  for (std::string_view w : {"flat", "smooth", "noperspective", "centroid", "sample", "invariant", "precise", "lowp",
                             "mediump", "highp", "in", "out", "patch", "const"})
    if (t.is(w)) return true;
  return false;
}

// Locations one value of this type takes (float/vector 1, matN/matNxM N), or nothing.
std::optional<int> locations_of(const std::string& type) {
  for (std::string_view scalar : {"float", "int", "uint", "bool"})
    if (type == scalar) return 1;
  for (std::string_view prefix : {"vec", "ivec", "uvec", "bvec"})
    if (type.starts_with(prefix) && type.size() == prefix.size() + 1) return 1;
  if (type.starts_with("mat") && type.size() >= 4 && std::isdigit(static_cast<unsigned char>(type[3])))
    return type[3] - '0';
  return std::nullopt;
}

// One varying a stage declares: the name it is matched by, where it goes.
struct Varying {
  std::string name;            // variable name, or the block name of an interface block
  int locations = 1;
  std::optional<int> location; // explicit, or assigned
  size_t first_token = 0;      // where "layout(location = N) " goes
  size_t comma = 0;            // 0: first declarator; else the ',' token it follows
  std::string redeclare;       // qualifiers and type, repeated after a split ','
};

struct StageVaryings {
  std::vector<Token> tokens;
  std::vector<Varying> varyings;
};

class Scanner {
 public:
  Scanner(const ShaderSource& source, const char* storage) : source_(source), storage_(storage) {}

  Result<StageVaryings> run() {
    StageVaryings out{cg::lex(source_.text), {}};
    const std::vector<Token>& t = out.tokens;
    size_t i = 0;
    while (i < t.size()) {
      if (t[i].kind == TokenKind::directive) {
        ++i;
        continue;
      }
      const size_t end = statement_end(t, i);
      if (auto ok = declaration(t, i, end, out.varyings); !ok) return std::unexpected(ok.error());
      i = end + 1;
    }
    return out;
  }

 private:
  // The index of the token ending the top-level statement that starts at `i`.
  static size_t statement_end(const std::vector<Token>& t, size_t i) {
    int braces = 0;
    bool parens_before_brace = false;
    for (; i < t.size(); ++i) {
      if (t[i].kind == TokenKind::directive) continue;
      if (t[i].is("(") && braces == 0) parens_before_brace = true;
      if (t[i].is("{")) ++braces;
      if (t[i].is("}") && --braces == 0 && parens_before_brace) return i;   // a function body
      if (t[i].is(";") && braces == 0) return i;
    }
    return t.size();
  }

  Error error_at(const Token& t, std::string message) const {
    return Error{.message = std::move(message), .file = source_.path, .line = t.physical_line, .stage = ErrorStage::compile};
  }

  Result<void> declaration(const std::vector<Token>& t, size_t begin, size_t end, std::vector<Varying>& out) const {
    size_t i = begin;
    bool storage = false;
    std::optional<int> explicit_location;
    while (i < end) {
      if (t[i].is("layout") && i + 1 < end && t[i + 1].is("(")) {
        for (i += 2; i < end && !t[i].is(")"); ++i)
          if (t[i].is("location") && i + 2 < end && t[i + 1].is("=") && t[i + 2].kind == TokenKind::number) {
            explicit_location = int_literal(t[i + 2].text);
            if (!explicit_location || *explicit_location >= kMaxLocations)
              return std::unexpected(error_at(t[i + 2], "layout location '" + t[i + 2].text +
                                                            "' is not an integer below " + std::to_string(kMaxLocations)));
          }
        ++i;
        continue;
      }
      if (!t[i].is_identifier() || !is_varying_qualifier(t[i])) break;
      storage = storage || t[i].is(storage_);
      ++i;
    }
    if (!storage || i >= end || !t[i].is_identifier()) return {};
    const size_t type = i;
    if (t[type].text.starts_with("gl_")) return {};   // a built-in block redeclared
    std::string redeclare;
    for (size_t k = begin; k <= type; ++k) redeclare += (k > begin ? " " : "") + t[k].text;

    if (i + 1 < end && t[i + 1].is("{")) {   // interface block: matched by block name
      int locations = 0;
      for (size_t k = i + 2; k < end && !t[k].is("}"); ++k) {
        if (!t[k].is_identifier() || is_varying_qualifier(t[k])) continue;
        auto per = locations_of(t[k].text);
        if (!per) return std::unexpected(error_at(t[k], "member type '" + t[k].text + "' of " + storage_ +
                                                            " block '" + t[type].text + "' has no known location "
                                                            "count; give the block a layout(location)"));
        for (++k; k < end && !t[k].is(";"); ++k)
          if (t[k].is_identifier()) locations += *per * array_length(t, k);
      }
      out.push_back({t[type].text, locations, explicit_location, begin, 0, {}});
      return {};
    }
    auto per = locations_of(t[type].text);
    if (!per && !explicit_location)
      return std::unexpected(error_at(t[type], std::string(storage_) + " variable of type '" + t[type].text +
                                                   "' has no known location count; give it a layout(location)"));
    size_t comma = 0;
    for (i = type + 1; i < end; ++i) {
      if (!t[i].is_identifier()) continue;
      if (t[i].text.starts_with("gl_")) return {};   // a built-in redeclared (gl_FragCoord)
      const int length = array_length(t, i);
      if (length < 0)
        return std::unexpected(error_at(t[i], std::string(storage_) + " array '" + t[i].text +
                                                  "' has no literal size (up to " + std::to_string(kMaxLocations) +
                                                  "); give it a layout(location)"));
      out.push_back({t[i].text, per.value_or(1) * length, comma ? std::nullopt : explicit_location, begin, comma,
                     redeclare});
      while (i < end && !t[i].is(",")) ++i;   // to the next declarator
      comma = i;
    }
    return {};
  }

  // The literal size of `name[N]` at tokens[i] (1 when not an array, -1 when not literal or above kMaxLocations).
  static int array_length(const std::vector<Token>& t, size_t i) {
    if (i + 1 >= t.size() || !t[i + 1].is("[")) return 1;
    if (i + 3 < t.size() && t[i + 2].kind == TokenKind::number && t[i + 3].is("]")) {
      if (auto n = int_literal(t[i + 2].text); n && *n <= kMaxLocations) return *n;
    }
    return -1;
  }

  const ShaderSource& source_;
  const char* storage_;
};

std::string layout(int location) { return "layout(location = " + std::to_string(location) + ") "; }

// Writes the assigned locations into the tokens; true when anything changed.
bool apply(StageVaryings& stage) {
  bool changed = false;
  for (const Varying& v : stage.varyings) {
    if (!v.location || v.comma == 0) continue;
    // A later declarator of "out vec3 a, b;" becomes its own declaration.
    stage.tokens[v.comma].text = "; " + layout(*v.location) + v.redeclare;
    changed = true;
  }
  return changed;
}

// Varying locations are core from GLSL 4.10; 3.30 to 4.00 get them from
// GL_ARB_separate_shader_objects, enabled right after #version (a #line keeps the lines).
void allow_output_locations(std::vector<Token>& tokens) {
  for (Token& t : tokens) {
    if (t.kind != TokenKind::directive) return;
    const GlslVersion version = glsl_version(t.text);
    if (!version.declared) continue;
    if (!version.es && version.number < 410)
      t.text += "\n#extension GL_ARB_separate_shader_objects : enable\n#line " + std::to_string(t.physical_line + 1);
    return;
  }
}

}  // namespace

Result<VaryingSources> assign_varying_locations(const ShaderSource& vertex, const ShaderSource& fragment) {
  auto vs = Scanner(vertex, "out").run();
  if (!vs) return std::unexpected(vs.error());
  auto fs = Scanner(fragment, "in").run();
  if (!fs) return std::unexpected(fs.error());

  std::set<int> taken;
  for (const Varying& v : vs->varyings)
    if (v.location)
      for (int k = 0; k < v.locations; ++k) taken.insert(*v.location + k);
  const auto free_run = [&](int size) {
    for (int at = 0;; ++at) {
      bool fits = true;
      for (int k = 0; k < size && fits; ++k) fits = !taken.contains(at + k);
      if (!fits) continue;
      for (int k = 0; k < size; ++k) taken.insert(at + k);
      return at;
    }
  };
  std::map<std::string, int> by_name;
  std::set<size_t> vs_assigned, fs_assigned;   // statements given a layout
  for (size_t n = 0; n < vs->varyings.size(); ++n) {
    Varying& v = vs->varyings[n];
    if (!v.location) {
      v.location = free_run(v.locations);
      if (v.comma == 0) vs_assigned.insert(n);
    }
    by_name[v.name] = *v.location;
  }
  for (size_t n = 0; n < fs->varyings.size(); ++n) {
    Varying& v = fs->varyings[n];
    if (v.location) continue;
    auto match = by_name.find(v.name);
    // No vertex output of that name: GL would not link it; give it a place of its own.
    v.location = match != by_name.end() ? match->second : free_run(v.locations);
    if (v.comma == 0) fs_assigned.insert(n);
  }

  const auto finish = [](StageVaryings& stage, const std::set<size_t>& first_declarators, const ShaderSource& source) {
    bool changed = apply(stage);
    for (size_t n : first_declarators) {
      const Varying& v = stage.varyings[n];
      stage.tokens[v.first_token].prefix = layout(*v.location) + stage.tokens[v.first_token].prefix;
      changed = true;
    }
    if (changed) allow_output_locations(stage.tokens);
    return changed ? cg::rebuild(source.text, stage.tokens) : source.text;
  };
  return VaryingSources{finish(*vs, vs_assigned, vertex), finish(*fs, fs_assigned, fragment)};
}

}  // namespace shaderbed
