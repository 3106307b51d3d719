#include "backends/Backend.h"

namespace shaderbed {

std::vector<ShaderPath> backend_paths(const std::string& backend, Language language) {
  if (backend != "gl") return {ShaderPath::spirv};
  if (language == Language::glsl) return {ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl};
  return {ShaderPath::spirv, ShaderPath::cross_glsl};
}

}  // namespace shaderbed
