#include "backends/Backend.h"

namespace shaderbed {

const char* to_string(ShaderPath p) {
  switch (p) {
    case ShaderPath::spirv: return "spirv";
    case ShaderPath::native_glsl: return "glsl";
    case ShaderPath::cross_glsl: return "cross";
  }
  return "?";
}

std::vector<ShaderPath> backend_paths(const std::string& backend, Language language) {
  if (backend != "gl") return {ShaderPath::spirv};
  if (language == Language::glsl) return {ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl};
  return {ShaderPath::spirv, ShaderPath::cross_glsl};
}

}  // namespace shaderbed
