#include "backends/VertexInputs.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>

#include "core/AsciiCase.h"

namespace shaderbed {
namespace {

// "InVertex.Position" -> "position"; "in_normal", "aNormal", "aPos", "attrTexCoord" -> the attribute word.
std::string attribute_word(std::string name) {
  if (auto dot = name.rfind('.'); dot != std::string::npos) name = name.substr(dot + 1);
  std::string l = ascii_lower(name);
  for (const char* prefix : {"attr_", "attr", "in_", "a_", "v_", "i_", "in", "a"}) {
    std::string p = prefix;
    if (l.size() > p.size() && l.starts_with(p)) {
      // Only strip a bare prefix when what follows starts a new word (inNormal, aNormal).
      const char next = name[p.size()];
      if (p.back() == '_' || std::isupper(static_cast<unsigned char>(next))) {
        l = l.substr(p.size());
        break;
      }
    }
  }
  return l;
}

// The legacy-GLSL dialect's inputs keep their built-in names (gl_Vertex, ...; compile/LegacyGlsl.h).
std::optional<AttributeStream> from_word(const std::string& w) {
  if (w == "position" || w == "pos" || w == "vertex" || w == "gl_vertex")
    return AttributeStream{VertexAttribute::position, offsetof(Vertex, position), 3};
  if (w == "normal" || w == "norm" || w == "gl_normal")
    return AttributeStream{VertexAttribute::normal, offsetof(Vertex, normal), 3};
  if (w == "tangent")
    return AttributeStream{VertexAttribute::tangent, offsetof(Vertex, tangent), 3};
  if (w == "binormal" || w == "bitangent")
    return AttributeStream{VertexAttribute::binormal, offsetof(Vertex, binormal), 3};
  if (w == "texcoord" || w == "texcoord0" || w == "uv" || w == "texcoords" || w == "gl_multitexcoord0")
    return AttributeStream{VertexAttribute::texcoord, offsetof(Vertex, uv), 2};
  if (w == "color" || w == "colour" || w == "color0" || w == "colour0" || w == "gl_color")
    return AttributeStream{VertexAttribute::color, offsetof(Vertex, color), 4};
  return std::nullopt;
}

std::optional<AttributeStream> from_extra(const std::string& word, const ExtraStreams* extra) {
  if (!extra) return std::nullopt;
  // "InVertex.sh_r0" reads the stream sh_r0: the struct's name is not part of it.
  const std::string name = ascii_lower(word.substr(word.rfind('.') == std::string::npos ? 0 : word.rfind('.') + 1));
  for (size_t k = 0; k < extra->names.size(); ++k)
    if (ascii_lower(extra->names[k]) == name)
      return AttributeStream{VertexAttribute::extra, uint32_t(16 * k), 4, 1};
  return std::nullopt;
}

const std::string* mapped_word(const StageInput& input, const AttributeTable* map) {
  if (!map) return nullptr;
  for (const std::string& key : {input.name, "location " + std::to_string(input.location)})
    if (auto it = map->find(key); it != map->end()) return &it->second;
  return nullptr;
}

std::string describe(const StageInput& input) {
  return "'" + input.name + "'" + (input.semantic.empty() ? "" : " (" + input.semantic + ")") + " at location " +
         std::to_string(input.location);
}

}  // namespace

Result<AttributeStream> attribute_stream_for(const StageInput& input, const AttributeTable* map,
                                             const ExtraStreams* extra) {
  if (const std::string* word = mapped_word(input, map)) {
    if (auto a = from_word(*word)) return *a;
    if (auto a = from_extra(*word, extra)) return *a;
    std::string streams;
    if (extra)
      for (const std::string& name : extra->names) streams += ", " + name;
    return fail(ErrorStage::bind, "vertex input " + describe(input) + " is mapped to '" + *word +
                            "', which is not a mesh attribute (position, normal, tangent, binormal, texcoord, color" + streams + ")");
  }
  if (auto a = from_extra(input.name, extra)) return *a;
  if (!input.semantic.empty()) {
    std::string s = ascii_lower(input.semantic);
    if (s == "position0" || s == "sv_position") s = "position";   // POSITION is #defined to SV_Position
    if (s == "normal0") s = "normal";
    if (s == "tangent0") s = "tangent";
    if (s == "binormal0") s = "binormal";
    if (auto a = from_word(s)) return *a;
  }
  if (auto a = from_word(attribute_word(input.name))) return *a;
  return fail(ErrorStage::bind, "vertex input " + describe(input) +
                          " is not a mesh attribute; use POSITION, NORMAL, TANGENT, BINORMAL, TEXCOORD0 or COLOR "
                          "(GLSL: position, normal, tangent, binormal, texcoord, color)");
}

Result<std::vector<AttributeStream>> attribute_streams_for(const std::vector<StageInput>& inputs,
                                                           const AttributeTable* map, Language language,
                                                           const ExtraStreams* extra) {
  std::vector<AttributeStream> streams;
  std::vector<std::string> unmatched;
  const StageInput* first = nullptr;
  for (const StageInput& input : inputs) {
    auto stream = attribute_stream_for(input, map, extra);
    if (stream) {
      streams.push_back(*stream);
    } else if (mapped_word(input, map)) {
      return std::unexpected(stream.error());   // a bad map entry says so itself
    } else {
      unmatched.push_back(describe(input));
      if (!first) first = &input;
    }
  }
  if (unmatched.empty()) return streams;
  std::string list;
  for (size_t i = 0; i < unmatched.size(); ++i) list += (i ? ", " : "") + unmatched[i];
  const std::string lang = to_string(language);
  return fail(ErrorStage::bind, std::string(unmatched.size() == 1 ? "vertex input " : "vertex inputs ") + list +
                          (unmatched.size() == 1 ? " is not a mesh attribute" : " are not mesh attributes") +
                          "; map each in the case under [attributes." + lang + "], by name or location (" +
                          first->name + " = \"normal\" or \"location " + std::to_string(first->location) +
                          "\" = \"normal\"; attributes: position, normal, tangent, binormal, texcoord, color)");
}

}  // namespace shaderbed
