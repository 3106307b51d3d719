#include "backends/VertexInputs.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>

#include "scene/Mesh.h"

namespace shaderbed {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// "InVertex.Position" -> "position"; "in_normal", "aNormal", "attrTexCoord" -> the attribute word.
std::string attribute_word(std::string name) {
  if (auto dot = name.rfind('.'); dot != std::string::npos) name = name.substr(dot + 1);
  std::string l = lower(name);
  for (const char* prefix : {"attr_", "attr", "in_", "a_", "v_", "i_", "in"}) {
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

std::optional<AttributeStream> from_word(const std::string& w) {
  if (w == "position" || w == "pos" || w == "vertex")
    return AttributeStream{VertexAttribute::position, offsetof(Vertex, position), 3};
  if (w == "normal" || w == "norm")
    return AttributeStream{VertexAttribute::normal, offsetof(Vertex, normal), 3};
  if (w == "tangent")
    return AttributeStream{VertexAttribute::tangent, offsetof(Vertex, tangent), 3};
  if (w == "texcoord" || w == "texcoord0" || w == "uv" || w == "texcoords")
    return AttributeStream{VertexAttribute::texcoord, offsetof(Vertex, uv), 2};
  return std::nullopt;
}

}  // namespace

Result<AttributeStream> attribute_stream_for(const StageInput& input) {
  if (!input.semantic.empty()) {
    std::string s = lower(input.semantic);
    if (s == "position0" || s == "sv_position") s = "position";   // POSITION is #defined to SV_Position
    if (s == "normal0") s = "normal";
    if (s == "tangent0") s = "tangent";
    if (auto a = from_word(s)) return *a;
  }
  if (auto a = from_word(attribute_word(input.name))) return *a;
  return fail("bind", "vertex input '" + input.name + "'" +
                          (input.semantic.empty() ? "" : " (" + input.semantic + ")") +
                          " at location " + std::to_string(input.location) +
                          " is not a mesh attribute; use POSITION, NORMAL, TANGENT or TEXCOORD0 "
                          "(GLSL: position, normal, tangent, texcoord)");
}

}  // namespace shaderbed
