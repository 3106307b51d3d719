#include "pipeline/ShaderPath.h"

namespace shaderbed {

const char* to_string(ShaderPath p) {
  switch (p) {
    case ShaderPath::spirv: return "spirv";
    case ShaderPath::native_glsl: return "glsl";
    case ShaderPath::cross_glsl: return "cross";
  }
  return "?";
}

}  // namespace shaderbed
