#include "stats/nir/NirText.h"

#include <array>
#include <cctype>
#include <optional>
#include <string>

namespace shaderbed {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool starts_with_word(std::string_view line, std::string_view word) {
  if (!line.starts_with(word)) return false;
  if (line.size() == word.size()) return true;
  const char next = line[word.size()];
  return !(std::isalnum(static_cast<unsigned char>(next)) || next == '_');
}

// nir_texop names as nir_print prints them (nir_print.c, Mesa 22.3).
constexpr std::array kTexOps = {"tex", "txb", "txl", "txd", "txf", "txf_ms", "txf_ms_fb", "txf_ms_mcs_intel",
                                "txs", "lod", "tg4", "query_levels", "texture_samples", "samples_identical",
                                "tex_prefetch", "fragment_fetch_amd", "fragment_mask_fetch_amd"};

// Right-hand-side opcodes that are not ALU instructions.
constexpr std::array kNotAlu = {"intrinsic", "load_const", "undefined", "phi", "parallel_copy",
                                "deref_var", "deref_array", "deref_struct", "deref_cast",
                                "deref_ptr_as_array", "deref_array_wildcard"};

template <size_t N>
bool one_of(std::string_view word, const std::array<const char*, N>& names) {
  for (const char* n : names)
    if (word == n) return true;
  return false;
}

// "vec4 32 ssa_5 = fmul ssa_3, ssa_4" or "r3 = fmul ..." -> "fmul ssa_3, ssa_4"; nullopt if
// the line defines nothing.
std::optional<std::string_view> definition_rhs(std::string_view line) {
  const size_t eq = line.find(" = ");
  if (eq == std::string_view::npos) return std::nullopt;
  const std::string_view lhs = trim(line.substr(0, eq));
  // SSA defs end with "ssa_N", registers (out of SSA) with "rN" (optionally "rN.xyz").
  const size_t space = lhs.rfind(' ');
  std::string_view dest = space == std::string_view::npos ? lhs : lhs.substr(space + 1);
  const bool ssa = dest.starts_with("ssa_");
  const bool reg = dest.size() > 1 && dest[0] == 'r' && std::isdigit(static_cast<unsigned char>(dest[1]));
  if (!ssa && !reg) return std::nullopt;
  return trim(line.substr(eq + 3));
}

std::string_view first_word(std::string_view s) {
  size_t n = 0;
  while (n < s.size() && (std::isalnum(static_cast<unsigned char>(s[n])) || s[n] == '_')) ++n;
  return s.substr(0, n);
}

std::string decode_xml(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const size_t semi = s.find(';', i);
    if (semi == std::string_view::npos) {
      out += s[i];
      continue;
    }
    const std::string_view entity = s.substr(i + 1, semi - i - 1);
    if (entity == "lt") out += '<';
    else if (entity == "gt") out += '>';
    else if (entity == "amp") out += '&';
    else if (entity == "quot") out += '"';
    else if (entity == "apos") out += '\'';
    else if (entity.starts_with('#')) {
      const bool hex = entity.size() > 1 && (entity[1] == 'x' || entity[1] == 'X');
      const unsigned long code = std::stoul(std::string(entity.substr(hex ? 2 : 1)), nullptr, hex ? 16 : 10);
      out += code < 0x80 ? static_cast<char>(code) : '?';
    } else {
      out.append(s.substr(i, semi - i + 1));
      continue;
    }
    i = semi;
  }
  return out;
}

std::optional<Stage> stage_of_header(std::string_view line) {
  // "shader: MESA_SHADER_FRAGMENT"
  if (line.find("MESA_SHADER_VERTEX") != std::string_view::npos) return Stage::vertex;
  if (line.find("MESA_SHADER_FRAGMENT") != std::string_view::npos) return Stage::fragment;
  return std::nullopt;
}

// Splits printed text into shaders at "shader: MESA_SHADER_*" lines. A shader ends at
// the closing brace of its function body (the "}" in column 0 after "impl"), so text
// printed between shaders (GLSL IR, trace XML) is not counted.
void split_shaders(std::string_view text, std::vector<NirShader>& out) {
  size_t pos = text.find("shader: MESA_SHADER_");
  while (pos != std::string_view::npos) {
    size_t next = text.find("shader: MESA_SHADER_", pos + 1);
    std::string_view block = text.substr(pos, next == std::string_view::npos ? text.size() - pos : next - pos);
    if (const size_t impl = block.find("\nimpl "); impl != std::string_view::npos)
      if (const size_t close = block.find("\n}", impl); close != std::string_view::npos)
        block = block.substr(0, close + 2);
    const std::string_view header = block.substr(0, block.find('\n'));
    if (auto stage = stage_of_header(header)) out.push_back(NirShader{*stage, std::string(block)});
    pos = next;
  }
}

}  // namespace

Result<NirCounts> count_nir(std::string_view text) {
  NirCounts c;
  bool has_impl = false;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(start, end - start));
    start = end + 1;
    if (line.empty() || line.starts_with("/*") || line.starts_with("//")) continue;
    if (starts_with_word(line, "impl")) {
      has_impl = true;
      continue;
    }
    if (starts_with_word(line, "if")) {
      ++c.ifs;
      continue;
    }
    if (starts_with_word(line, "loop")) {
      ++c.loops;
      continue;
    }
    if (starts_with_word(line, "break") || starts_with_word(line, "continue") || starts_with_word(line, "return") ||
        starts_with_word(line, "halt") || starts_with_word(line, "goto") || starts_with_word(line, "goto_if")) {
      ++c.jumps;
      continue;
    }
    if (starts_with_word(line, "intrinsic")) {   // stores and other intrinsics without a destination
      ++c.intrinsics;
      continue;
    }
    const auto rhs = definition_rhs(line);
    if (!rhs) continue;
    std::string_view op = *rhs;
    if (op.starts_with('(')) {   // "(float32)tex ..." : texture instructions print their result type first
      const size_t close = op.find(')');
      if (close == std::string_view::npos) continue;
      op = op.substr(close + 1);
    }
    const std::string_view word = first_word(op);
    if (word.empty()) continue;
    if (one_of(word, kTexOps)) {
      ++c.tex;
    } else if (word == "intrinsic") {
      ++c.intrinsics;
    } else if (word == "load_const") {
      ++c.load_consts;
    } else if (!one_of(word, kNotAlu)) {
      ++c.alu;
    }
  }
  if (!has_impl) return fail(ErrorStage::nir, "no NIR function body (\"impl\") in the captured text");
  c.control = c.ifs + c.loops + c.jumps;
  return c;
}

std::vector<NirShader> nir_from_gallium_trace(std::string_view xml) {
  // trace_dump_nir (Mesa 22.3) writes the printed NIR as the pipe_shader_state's 'ir'
  // member: <string><![CDATA[shader: MESA_SHADER_...]]></string>. Older traces escaped
  // it as text; both are read.
  std::vector<NirShader> out;
  size_t pos = 0;
  bool any_cdata = false;
  while ((pos = xml.find("<![CDATA[", pos)) != std::string_view::npos) {
    pos += 9;
    const size_t end = xml.find("]]>", pos);
    if (end == std::string_view::npos) break;
    any_cdata = true;
    split_shaders(xml.substr(pos, end - pos), out);
    pos = end + 3;
  }
  if (!any_cdata) split_shaders(decode_xml(xml), out);
  return out;
}

std::vector<NirShader> nir_from_printed_text(std::string_view text) {
  std::vector<NirShader> out;
  split_shaders(text, out);
  return out;
}

}  // namespace shaderbed
