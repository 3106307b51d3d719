#include "compile/CgDialect.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <optional>

#include "compile/CgTokens.h"
#include "core/AsciiCase.h"
#include "pipeline/SpirvWords.h"

namespace shaderbed {
namespace {

using cg::Token;
using cg::TokenKind;

bool starts_with_digits(std::string_view s, std::string_view prefix, int lo, int hi, int* value = nullptr) {
  if (!s.starts_with(prefix) || s.size() == prefix.size()) return false;
  int n = 0;
  for (char c : s.substr(prefix.size())) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    n = n * 10 + (c - '0');
    if (n > 1000) return false;
  }
  if (n < lo || n > hi) return false;
  if (value) *value = n;
  return true;
}

Error unsupported(const Token& at, const std::string& construct, const std::string& reason) {
  return Error{.message = "Cg feature '" + construct + "' is not supported by shaderbed's Cg layer (no Cg compiler; " +
                          reason + ")",
               .file = at.file,
               .line = at.line,
               .stage = ErrorStage::compile};
}

// ---- pass 1 -----------------------------------------------------------------------

std::string pragma_name(std::string_view directive) {
  std::string_view d = directive.substr(1);
  const auto skip = [&] {
    while (!d.empty() && (d.front() == ' ' || d.front() == '\t')) d.remove_prefix(1);
  };
  skip();
  if (!d.starts_with("pragma")) return {};
  d.remove_prefix(6);
  if (!d.empty() && d.front() != ' ' && d.front() != '\t') return {};
  skip();
  std::size_t n = 0;
  while (n < d.size() && (std::isalnum(static_cast<unsigned char>(d[n])) || d[n] == '_')) ++n;
  return n == 0 ? std::string("(empty)") : std::string(d.substr(0, n));
}

// Why a Cg #pragma is dropped. glslang ignores unknown pragmas anyway; dropping them
// here records the decision and keeps glslang from warning about `once`.
std::string pragma_reason(const std::string& name) {
  static const std::map<std::string, std::string> reasons = {
      {"profileoption", "a Cg profile option; there is no Cg profile, the target is SPIR-V"},
      {"option", "a Cg compiler option; there is no Cg compiler"},
      {"optionNV", "an NVIDIA Cg compiler option; there is no Cg compiler"},
      {"profile", "selects a Cg profile; the target is SPIR-V"},
      {"entry", "names the Cg entry; the case file names it"},
      {"bind", "binds a parameter to a Cg register; shaderbed binds uniforms by name from reflection"},
      {"fastmath", "a Cg precision switch; precision is fp32"},
      {"fastprecision", "a Cg precision switch; precision is fp32"},
      {"debug", "a compiler switch glslang's HLSL front end does not have"},
      {"optimize", "a compiler switch glslang's HLSL front end does not have; SPIR-V is optimised separately"},
      {"once", "honoured by shaderbed's includer"},
  };
  if (auto it = reasons.find(name); it != reasons.end()) return it->second;
  return "unknown #pragma, ignored as the Cg compiler ignores it";
}

// ---- pass 3 -----------------------------------------------------------------------

// half/fixed and their vectors and matrices are fp32 floats: precision is not emulated.
std::optional<std::string> float_spelling(std::string_view id) {
  for (std::string_view base : {std::string_view("half"), std::string_view("fixed")}) {
    if (!id.starts_with(base)) continue;
    std::string_view rest = id.substr(base.size());
    if (rest.empty()) return std::string("float");
    const bool vec = rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4';
    const bool mat =
        rest.size() == 3 && rest[0] >= '1' && rest[0] <= '4' && rest[1] == 'x' && rest[2] >= '1' && rest[2] <= '4';
    if (vec || mat) return "float" + std::string(rest);
  }
  return std::nullopt;
}

bool is_sampler_type(std::string_view id) {
  return id == "sampler" || id == "sampler1D" || id == "sampler2D" || id == "sampler3D" || id == "samplerCUBE";
}

bool one_of(std::string_view id, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), id) != names.end();
}

// Cg's typed lookups: f/h/x, 1-4 components, a texture function (f1tex2D, h4texCUBEproj...).
bool typed_lookup(std::string_view id) {
  if (id.size() < 6 || !(id[0] == 'f' || id[0] == 'h' || id[0] == 'x') || id[1] < '1' || id[1] > '4') return false;
  std::string_view rest = id.substr(2);
  for (std::string_view fn : {"tex1D", "tex2D", "tex3D", "texCUBE", "texRECT"}) {
    if (!rest.starts_with(fn)) continue;
    std::string_view form = rest.substr(fn.size());
    return one_of(form, {"", "proj", "bias", "lod", "grad", "fetch", "size"});
  }
  return false;
}

// Identifiers that name an unsupported Cg feature wherever they appear (whole
// identifiers only: texRECTangle is someone's variable).
std::optional<std::string> unsupported_identifier(std::string_view id) {
  if (one_of(id, {"samplerRECT", "texRECT", "texRECTproj", "texRECTbias", "texRECTlod", "texRECTgrad", "texRECTfetch",
                  "texRECTsize"}))
    return "rectangle textures have no Vulkan equivalent";
  if (id == "tex1Dproj" || id == "tex2Dproj")
    return "Cg divides a float2/float3 coordinate by its last component and makes the longer form a depth "
           "comparison, while glslang's HLSL front end takes float4 and divides by .w; write tex1D(s, c.x / c.y) or "
           "tex2D(s, c.xy / c.z)";
  if (id == "texCUBEproj")
    return "SPIR-V has no projective cube-map lookup and a cube direction needs no division; write texCUBE(s, c.xyz)";
  if (one_of(id, {"samplerBUF", "texBUF", "texBUFsize"}))
    return "buffer textures have no DX9-HLSL spelling for glslang's front end and shaderbed binds none";
  if (id == "interface")
    return "Cg interfaces are implemented by run-time bound structs (cgConnectParameter); HLSL and SPIR-V have no "
           "equivalent";
  if (id == "packed") return "Cg's packed storage qualifier has no HLSL equivalent";
  if (typed_lookup(id))
    return "Cg's typed lookups include depth-compare overloads that cannot be told apart without Cg's type checker; "
           "use tex1D/tex2D/tex3D/texCUBE and a swizzle";
  return std::nullopt;
}

// Unsupported functions: only a call is an error (a variable may be called "noise").
std::optional<std::string> unsupported_call(std::string_view id) {
  if (id == "noise") return "noise() crashes glslang's HLSL front end and has no SPIR-V equivalent";
  if (one_of(id, {"pack_2half", "pack_2ushort", "pack_4byte", "pack_4ubyte", "unpack_2half", "unpack_2ushort",
                  "unpack_4byte", "unpack_4ubyte"}))
    return "Cg's bit-packing functions have no HLSL equivalent in glslang";
  return std::nullopt;
}

struct SemanticMapping {
  std::string mapped;                // what glslang sees (may be "register(sN)")
  std::optional<std::string> error;  // unsupported semantic: the reason
};

SemanticMapping map_semantic(const std::string& s, Stage stage) {
  const bool vertex = stage == Stage::vertex;
  int n = 0;
  if (s == "POSITION" || s == "HPOS") return {"SV_Position", {}};
  if (s == "WPOS") {
    if (vertex) return {s, "WPOS is a fragment-program input (the window position)"};
    return {"SV_Position", {}};
  }
  if (s == "FACE") {
    if (vertex) return {s, "FACE is a fragment-program input"};
    return {"SV_IsFrontFace", {}};
  }
  if (s == "COL" || s == "COLOR") return {"COLOR", {}};
  if (s == "COL0") return {"COLOR0", {}};
  if (s == "COL1") return {"COLOR1", {}};
  if (starts_with_digits(s, "TEX", 0, 7, &n)) return {"TEXCOORD" + std::to_string(n), {}};
  if (s == "DEPTH" || s == "DEPR") {
    if (vertex) return {s, "DEPTH is a fragment-program output"};
    return {"SV_Depth", {}};
  }
  if (s == "PSIZ" || s == "PSIZE") {
    if (!vertex) return {s, "the point size is a vertex-program output; a fragment program cannot read it"};
    return {"PSIZE", {}};
  }
  if (s == "BCOL0" || s == "BCOL1")
    return {s,
            "back-face colours (two-sided vertex colour selection) are fixed-function state with no Vulkan "
            "equivalent"};
  if (s == "FOG" || s == "FOGP" || s == "FOGC" || s == "FOGCOORD")
    return {s, "the fixed-function fog coordinate has no Vulkan equivalent"};
  if (starts_with_digits(s, "CLP", 0, 5))
    return {s, "user clip planes need API clip-distance enables that shaderbed's backends do not make"};
  if (starts_with_digits(s, "TEXUNIT", 0, 31, &n)) return {"register(s" + std::to_string(n) + ")", {}};
  if (starts_with_digits(s, "ATTR", 0, 15, &n)) {
    if (!vertex) return {s, "ATTR0-15 are vertex-program inputs"};
    // NVIDIA's attribute aliasing (Cg arbvp1/vp40 profiles).
    static const std::array<const char*, 16> alias = {
        "SV_Position", "BLENDWEIGHT", "NORMAL",    "COLOR0",    "COLOR1",    "FOGCOORD",  "PSIZE",   "BLENDINDICES",
        "TEXCOORD0",   "TEXCOORD1",   "TEXCOORD2", "TEXCOORD3", "TEXCOORD4", "TEXCOORD5", "TANGENT", "BINORMAL"};
    return {alias[static_cast<std::size_t>(n)], {}};
  }
  return {s, {}};
}

// The first token of the declaration that ends at `name_index` (walks back over the
// return type and qualifiers).
std::size_t declaration_start(const std::vector<Token>& t, std::size_t name_index) {
  std::size_t i = name_index;
  while (i > 0 && t[i - 1].is_identifier() && !t[i - 1].removed) --i;
  return i;
}

std::size_t matching_close(const std::vector<Token>& t, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < t.size(); ++i) {
    if (t[i].kind != TokenKind::punctuation) continue;
    if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
    if (t[i].is(")") || t[i].is("]") || t[i].is("}"))
      if (--depth == 0) return i;
  }
  return t.size();
}

}  // namespace

// ---- pass 1 -----------------------------------------------------------------------

Result<CgPreparedFile> prepare_cg_file(std::string_view text, const std::string& path) {
  CgPreparedFile out;
  std::vector<Token> tokens = cg::lex(text);
  for (Token& t : tokens) {
    if (t.kind == TokenKind::directive) {
      const std::string name = pragma_name(t.text);
      if (name.empty() || name == "pack_matrix") continue;  // glslang applies pack_matrix as HLSL does
      if (name == "once") out.pragma_once = true;
      t.removed = true;
      out.notes.push_back({path, t.physical_line, "#pragma " + name + " dropped: " + pragma_reason(name)});
    } else if (t.kind == TokenKind::number && !t.text.starts_with("0x") && !t.text.starts_with("0X")) {
      // Cg's half (h) and fixed (x) literal suffixes: the value is an fp32 float here.
      while (!t.text.empty() &&
             (t.text.back() == 'h' || t.text.back() == 'H' || t.text.back() == 'x' || t.text.back() == 'X'))
        t.text.pop_back();
    }
  }
  out.text = cg::rebuild(text, tokens);
  return out;
}

// ---- pass 3 -----------------------------------------------------------------------

Result<CgTranslation> translate_cg(std::string_view preprocessed, const std::string& path, Stage stage,
                                   const std::string& entry_point) {
  CgTranslation out;
  std::vector<Token> t = cg::lex(preprocessed);
  cg::assign_positions(t, path);

  bool need_lit = false;
  int paren_depth = 0;
  int pending_ternaries = 0;
  bool in_case_label = false;
  std::map<std::size_t, std::string> semantic_at;  // token index -> mapped semantic, in source order

  for (std::size_t i = 0; i < t.size(); ++i) {
    Token& tok = t[i];
    const Token* next = i + 1 < t.size() ? &t[i + 1] : nullptr;
    switch (tok.kind) {
      case TokenKind::identifier: {
        if (auto why = unsupported_identifier(tok.text)) return std::unexpected(unsupported(tok, tok.text, *why));
        if (next && next->is("("))
          if (auto why = unsupported_call(tok.text)) return std::unexpected(unsupported(tok, tok.text, *why));
        if (auto f = float_spelling(tok.text)) {
          tok.text = *f;
        } else if (tok.is("varying")) {
          tok.removed = true;  // Cg's default for entry parameters; HLSL has no such word
        } else if (tok.is("lit") && next && next->is("(")) {
          tok.text = "shaderbed_cg_lit";
          need_lit = true;
        } else if (tok.is("case") || tok.is("default")) {
          in_case_label = true;
        }
        break;
      }
      case TokenKind::number:
        if (!tok.text.starts_with("0x") && !tok.text.starts_with("0X"))
          while (!tok.text.empty() && (tok.text.back() == 'h' || tok.text.back() == 'H')) tok.text.pop_back();
        break;
      case TokenKind::punctuation: {
        if (tok.is("(") || tok.is("[")) ++paren_depth;
        if (tok.is(")") || tok.is("]")) --paren_depth;
        if (tok.is(";") || tok.is("{") || tok.is("}")) {
          pending_ternaries = 0;
          in_case_label = false;
        }
        if (tok.is("?")) ++pending_ternaries;
        // Unsized array parameter: "[ ]" followed by "," or ")" inside a parameter list.
        if (tok.is("[") && next && next->is("]") && i + 2 < t.size() && (t[i + 2].is(",") || t[i + 2].is(")")) &&
            paren_depth > 1) {
          const std::string name = i > 0 && t[i - 1].is_identifier() ? t[i - 1].text : std::string("?");
          return std::unexpected(unsupported(tok, "unsized array parameter '" + name + "[]'",
                                             "unsized arrays are sized by the Cg runtime (cgSetArraySize); SPIR-V "
                                             "needs every array's size at compile time"));
        }
        if (!tok.is(":")) break;
        if (pending_ternaries > 0) {
          --pending_ternaries;
          break;
        }
        if (in_case_label) {
          in_case_label = false;
          break;
        }
        if (i == 0 || !next || !next->is_identifier()) break;
        const Token& before = t[i - 1];
        if (!(before.is_identifier() || before.is(")") || before.is("]"))) break;
        if (next->is("register") || next->is("packoffset")) break;
        // A semantic.
        Token& sem = t[i + 1];
        const std::string written = ascii_upper(sem.text);
        SemanticMapping m = map_semantic(written, stage);
        if (m.error) return std::unexpected(unsupported(sem, "semantic " + sem.text, *m.error));
        out.semantics.push_back({written, ascii_upper(m.mapped), sem.file, sem.line});
        if (m.mapped != written) sem.text = m.mapped;
        semantic_at[i + 1] = ascii_upper(m.mapped);
        break;
      }
      default:
        break;
    }
  }

  // The entry function's definition: its parameters may need rewriting.
  std::optional<std::size_t> entry, open, close, body;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (!t[i].is_identifier() || t[i].text != entry_point || !t[i + 1].is("(")) continue;
    const std::size_t c = matching_close(t, i + 1);
    std::size_t j = c + 1;
    if (j < t.size() && t[j].is(":")) j += 2;  // return semantic
    if (j < t.size() && t[j].is("{")) {
      entry = i;
      open = i + 1;
      close = c;
      body = j;
      break;
    }
  }

  // FACE anywhere but on an entry parameter cannot be converted to Cg's +-1.
  for (const auto& [index, mapped] : semantic_at) {
    if (mapped != "SV_ISFRONTFACE") continue;
    if (!entry || index < *open || index > *close)
      return std::unexpected(unsupported(t[index], "semantic FACE outside the entry parameters",
                                         "shaderbed converts the front-facing flag to Cg's +1/-1 only on a parameter "
                                         "of the entry function"));
  }

  if (entry) {
    out.entry_file = t[*entry].file;
    out.entry_line = t[*entry].line;
    // Split the parameter list at top-level commas.
    std::vector<std::pair<std::size_t, std::size_t>> params;  // [first, last)
    std::size_t first = *open + 1;
    int depth = 0;
    for (std::size_t i = *open + 1; i < *close; ++i) {
      if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
      if (t[i].is(")") || t[i].is("]") || t[i].is("}")) --depth;
      if (depth == 0 && t[i].is(",")) {
        params.emplace_back(first, i);
        first = i + 1;
      }
    }
    if (first < *close) params.emplace_back(first, *close);

    std::string hoisted;
    for (std::size_t p = 0; p < params.size(); ++p) {
      const auto [a, b] = params[p];
      bool is_uniform = false, is_sampler = false;
      std::optional<std::size_t> face;
      for (std::size_t i = a; i < b; ++i) {
        is_uniform |= t[i].is("uniform");
        is_sampler |= t[i].is_identifier() && is_sampler_type(t[i].text);
        if (auto it = semantic_at.find(i); it != semantic_at.end() && it->second == "SV_ISFRONTFACE") face = i;
      }
      if (is_uniform && is_sampler) {
        // glslang neither auto-maps nor shifts the binding of a sampler that is an entry
        // parameter (they all land on binding 0); as a global it is bound like HLSL's.
        std::string decl;
        for (std::size_t i = a; i < b; ++i) {
          if (t[i].removed || t[i].is("in") || t[i].is("const")) continue;
          if (!decl.empty() && t[i].is_identifier() && decl.back() != '(') decl += ' ';
          decl += t[i].text;
          t[i].removed = true;
        }
        hoisted += decl + "; ";
        // Drop one comma next to the parameter.
        if (b < *close && t[b].is(","))
          t[b].removed = true;
        else if (a > *open + 1 && t[a - 1].is(","))
          t[a - 1].removed = true;
        out.notes.push_back({t[a].file, t[a].line,
                             "uniform sampler parameter moved to a global declaration so it gets its own binding"});
      } else if (face) {
        // name : FACE  ->  bool shaderbed_face_name : SV_IsFrontFace, and the body starts
        // with "float name = shaderbed_face_name ? 1.0 : -1.0;" (Cg's FACE is +-1).
        const std::size_t name = *face - 2;
        if (name < a || !t[name].is_identifier() || name == a || !t[name - 1].is_identifier())
          return std::unexpected(
              unsupported(t[*face], "semantic FACE on this parameter", "write it as 'float name : FACE'"));
        Token& type = t[name - 1];
        if (type.text != "bool") {
          const std::string user_type = type.text;
          const std::string var = t[name].text;
          type.text = "bool";
          t[name].text = "shaderbed_face_" + var;
          t[*body].suffix += " " + user_type + " " + var + " = shaderbed_face_" + var + " ? 1.0 : -1.0;";
          out.notes.push_back({t[name].file, t[name].line, "FACE read from SV_IsFrontFace and converted to +1/-1"});
        }
      }
    }
    if (!hoisted.empty()) t[declaration_start(t, *entry)].prefix = hoisted;
  }

  if (need_lit) {
    // Cg's lit(): (1, max(N.L, 0), N.L < 0 || N.H < 0 ? 0 : N.H^m, 1). glslang 12's own
    // lit multiplies instead of raising to the power.
    out.helpers +=
        "float4 shaderbed_cg_lit(float NdotL, float NdotH, float m)\n"
        "{\n"
        "    float specular = (NdotL < 0.0 || NdotH < 0.0) ? 0.0 : pow(max(NdotH, 0.0), m);\n"
        "    return float4(1.0, max(NdotL, 0.0), specular, 1.0);\n"
        "}\n";
  }
  out.text = cg::rebuild(preprocessed, t);
  return out;
}

// ---- pass 4 -----------------------------------------------------------------------

int cg_varying_location(std::string_view semantic) {
  const std::string s = ascii_upper(semantic);
  int n = 0;
  if (s == "TEXCOORD") return 0;
  if (starts_with_digits(s, "TEXCOORD", 0, 7, &n)) return n;
  if (s == "COLOR" || s == "COLOR0") return 8;
  if (s == "COLOR1") return 9;
  return -1;
}

namespace {

// Fragment colour outputs: COLOR/COLORn (and HLSL's SV_Target) -> render target n.
int cg_target_location(std::string_view semantic) {
  const std::string s = ascii_upper(semantic);
  int n = 0;
  if (s == "COLOR" || s == "SV_TARGET") return 0;
  if (starts_with_digits(s, "COLOR", 0, 3, &n) || starts_with_digits(s, "SV_TARGET", 0, 7, &n)) return n;
  return -1;
}

}  // namespace

Result<void> assign_cg_varying_locations(std::vector<uint32_t>& spirv, Stage stage, const CgTranslation& translation,
                                         const std::string& path) {
  if (spirv.size() < kSpirvHeaderWords) return {};
  constexpr uint32_t kStorageInput = std::to_underlying(spv::StorageClass::Input);
  constexpr uint32_t kStorageOutput = std::to_underlying(spv::StorageClass::Output);
  struct Variable {
    uint32_t storage = 0;
    uint32_t pointer_type = 0;
    std::string name;
    std::string semantic;
    std::size_t location_word = 0;  // index of the Location literal, 0 = none
    bool builtin = false;
  };
  std::map<uint32_t, Variable> vars;
  std::map<uint32_t, uint32_t> pointee, constants;
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> arrays;    // id -> (element, length id)
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> matrices;  // id -> (column, count)
  std::map<uint32_t, std::vector<uint32_t>> structs;
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, std::string> semantics;
  std::map<uint32_t, std::size_t> location_words;
  std::map<uint32_t, bool> builtins;

  // An instruction too short for the operands read (only a malformed module has one) is skipped.
  for (const SpirvInstruction in : SpirvInstructions(spirv)) {
    const std::span<const uint32_t> w = in.words;
    switch (in.opcode) {
      case spv::Op::OpName:
        if (w.size() >= 2) names[w[1]] = spirv_literal_string(w.subspan(2));
        break;
      case spv::Op::OpTypePointer:
        if (w.size() >= 4) pointee[w[1]] = w[3];
        break;
      case spv::Op::OpTypeArray:
        if (w.size() >= 4) arrays[w[1]] = {w[2], w[3]};
        break;
      case spv::Op::OpTypeMatrix:
        if (w.size() >= 4) matrices[w[1]] = {w[2], w[3]};
        break;
      case spv::Op::OpTypeStruct:
        if (w.size() >= 2) structs[w[1]] = std::vector<uint32_t>(w.begin() + 2, w.end());
        break;
      case spv::Op::OpConstant:
        if (w.size() >= 4) constants[w[2]] = w[3];
        break;
      case spv::Op::OpVariable:
        if (w.size() >= 4 && (w[3] == kStorageInput || w[3] == kStorageOutput))
          vars[w[2]] = {.storage = w[3], .pointer_type = w[1]};
        break;
      case spv::Op::OpDecorate:
        if (w.size() >= 4 && w[2] == std::to_underlying(spv::Decoration::Location))
          location_words[w[1]] = in.offset + 3;
        if (w.size() >= 3 && w[2] == std::to_underlying(spv::Decoration::BuiltIn)) builtins[w[1]] = true;
        break;
      case spv::Op::OpDecorateString:
        if (w.size() >= 3 && w[2] == std::to_underlying(spv::Decoration::UserSemantic))
          semantics[w[1]] = spirv_literal_string(w.subspan(3));
        break;
      default:
        break;
    }
  }

  // Locations a type occupies (32-bit components: one per vector, per matrix column).
  const auto slots = [&](auto&& self, uint32_t type) -> uint32_t {
    if (auto a = arrays.find(type); a != arrays.end()) {
      auto c = constants.find(a->second.second);
      return (c == constants.end() ? 1u : c->second) * self(self, a->second.first);
    }
    if (auto m = matrices.find(type); m != matrices.end()) return m->second.second;
    if (auto s = structs.find(type); s != structs.end()) {
      uint32_t n = 0;
      for (uint32_t member : s->second) n += self(self, member);
      return n;
    }
    return 1;
  };

  const auto where = [&](const std::string& semantic) -> std::pair<std::string, int> {
    for (const CgSemanticUse& u : translation.semantics)
      if (u.mapped == semantic) return {u.file, u.line};
    return {path, 0};
  };

  struct Placed {
    uint32_t first, count;
    std::string what;
  };
  std::vector<Placed> placed[2];  // [0] inputs, [1] outputs
  for (auto& [id, v] : vars) {
    if (builtins.contains(id) || !location_words.contains(id)) continue;
    const bool output = v.storage == kStorageOutput;
    if (stage == Stage::vertex && !output) continue;  // attributes are matched by semantic, not location
    if (!semantics.contains(id)) {
      // Cg requires a semantic on every varying; without one glslang numbers it by order,
      // which could collide with a semantic's location.
      const std::string name = names.contains(id) ? names[id] : "?";
      const std::string what = name == "@entryPointOutput" ? std::string("the return value")
                                                           : std::string(output ? "output '" : "input '") + name + "'";
      return std::unexpected(Error{.message = "Cg program: " + what +
                                              " of the entry function has no semantic (Cg needs one: "
                                              "TEXCOORD0-7, COLOR0/COLOR1, or COLOR for a fragment program's result)",
                                   .file = translation.entry_file.empty() ? path : translation.entry_file,
                                   .line = translation.entry_line,
                                   .stage = ErrorStage::compile});
    }
    const std::string semantic = ascii_upper(semantics[id]);
    const bool target = stage == Stage::fragment && output;
    const int location = target ? cg_target_location(semantic) : cg_varying_location(semantic);
    const std::string name = names.contains(id) ? names[id] : "?";
    if (location < 0) {
      auto [file, line] = where(semantic);
      const std::string role =
          target ? "fragment-program output" : (output ? "vertex-program output" : "fragment-program input");
      return std::unexpected(
          Error{.message = "Cg semantic '" + semantic + "' on " + role + " '" + name + "' is not a Cg " +
                           (target ? "colour output (use COLOR, COLOR0-3 or DEPTH)"
                                   : "varying (shaderbed links Cg varyings by semantic: TEXCOORD0-7, COLOR0, COLOR1)"),
                .file = file,
                .line = line,
                .stage = ErrorStage::compile});
    }
    const uint32_t n = slots(slots, pointee[v.pointer_type]);
    for (const Placed& p : placed[output])
      if (static_cast<uint32_t>(location) < p.first + p.count && p.first < static_cast<uint32_t>(location) + n) {
        auto [file, line] = where(semantic);
        return std::unexpected(Error{.message = "Cg varying '" + name + "' (" + semantic + ", " + std::to_string(n) +
                                                " location(s)) overlaps " + p.what,
                                     .file = file,
                                     .line = line,
                                     .stage = ErrorStage::compile});
      }
    placed[output].push_back({static_cast<uint32_t>(location), n, "'" + name + "' (" + semantic + ")"});
    spirv[location_words[id]] = static_cast<uint32_t>(location);
  }
  return {};
}

}  // namespace shaderbed
