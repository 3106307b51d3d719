#include "compile/ShaderLabFrontEnd.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

namespace shaderbed {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A line without its // comment, trimmed.
std::string_view code_of(std::string_view line) {
  if (const size_t comment = line.find("//"); comment != std::string_view::npos) line = line.substr(0, comment);
  return trimmed(line);
}

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
    if (end == std::string_view::npos) break;
    at = end + 1;
  }
  return lines;
}

// "#pragma vertex vert" -> {"vertex", "vert"}; anything else -> {"", ""}.
std::pair<std::string, std::string> pragma_of(std::string_view code) {
  if (!code.starts_with("#")) return {};
  code = trimmed(code.substr(1));
  if (!code.starts_with("pragma")) return {};
  code = trimmed(code.substr(6));
  const size_t space = code.find_first_of(" \t");
  if (space == std::string_view::npos) return {};
  const std::string_view name = code.substr(0, space), value = trimmed(code.substr(space));
  if (value.empty() || value.find_first_of(" \t") != std::string_view::npos) return {};
  return {std::string(name), std::string(value)};
}

Error at_line(const std::string& path, int line, std::string message) {
  return Error{.message = std::move(message), .file = path, .line = line, .stage = ErrorStage::compile};
}

}  // namespace

bool is_shaderlab_file(const std::string& path, std::string_view text) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".shader") return true;
  for (std::string_view line : lines_of(text)) {
    const std::string_view code = code_of(line);
    if (code.empty()) continue;
    return code.starts_with("Shader") && trimmed(code.substr(6)).starts_with("\"");
  }
  return false;
}

Result<ShaderLabProgram> extract_shaderlab_program(std::string_view text, const std::string& path) {
  const std::vector<std::string_view> lines = lines_of(text);
  std::vector<bool> keep(lines.size(), false);
  ShaderLabProgram out;
  int vertex_line = 0, fragment_line = 0;
  // open: the line of the block being read (0 = outside); program: it is the program.
  size_t open = 0;
  bool program = false, found = false;
  std::string_view closing;
  for (size_t i = 0; i < lines.size() && !found; ++i) {
    const std::string_view code = code_of(lines[i]);
    if (!open) {
      const bool cg = code == "CGPROGRAM" || code == "CGINCLUDE";
      if (cg || code == "HLSLPROGRAM" || code == "HLSLINCLUDE") {
        open = i + 1;
        program = code.ends_with("PROGRAM");
        closing = cg ? "ENDCG" : "ENDHLSL";
        if (program) out.hlsl_block = !cg, out.block_line = int(i + 1);
      }
      continue;
    }
    if (code == closing) {
      found = program;
      open = 0;
      continue;
    }
    if (code == "ENDCG" || code == "ENDHLSL")
      return std::unexpected(at_line(path, int(i + 1), std::string(code) + " closes the block opened at line " +
                                                           std::to_string(open) + ", which " + std::string(closing) +
                                                           " closes"));
    keep[i] = true;
    if (!program) continue;
    const auto [pragma, entry] = pragma_of(code);
    if (pragma == "vertex" || pragma == "fragment") {
      (pragma == "vertex" ? out.vertex_entry : out.fragment_entry) = entry;
      (pragma == "vertex" ? vertex_line : fragment_line) = int(i + 1);
      keep[i] = false;   // Unity's directive, not HLSL's
    }
  }
  if (open)
    return std::unexpected(at_line(path, int(open), "the block opened here has no " + std::string(closing)));
  if (!found)
    return std::unexpected(at_line(path, 0, "no CGPROGRAM or HLSLPROGRAM block in this ShaderLab file"));
  for (size_t i = 0; i < lines.size(); ++i) {
    if (keep[i]) out.text += lines[i];
    if (i + 1 < lines.size()) out.text += '\n';
  }
  return out;
}

Result<ProgramSource> prepare_shaderlab_program(const ProgramSource& program) {
  ProgramSource out = program;
  for (ShaderSource* stage : {&out.vertex, &out.fragment}) {
    if (!is_shaderlab_file(stage->path, stage->text)) continue;
    auto extracted = extract_shaderlab_program(stage->text, stage->path);
    if (!extracted) return std::unexpected(extracted.error());
    const bool vertex = stage->stage == Stage::vertex;
    const std::string& pragma_entry = vertex ? extracted->vertex_entry : extracted->fragment_entry;
    if (stage->entry_point == "main") {
      if (pragma_entry.empty())
        return std::unexpected(at_line(stage->path, extracted->block_line,
                                       std::string("the program block has no #pragma ") +
                                           (vertex ? "vertex" : "fragment") + " naming its entry (or name it in the case as " +
                                           (vertex ? "vertex_entry" : "fragment_entry") + ")"));
      stage->entry_point = pragma_entry;
    }
    stage->text = std::move(extracted->text);
  }
  return out;
}

}  // namespace shaderbed
