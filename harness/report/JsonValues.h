#pragma once
// Pieces every JSON file shaderbed writes shares (results, sweep, bench, hard), so a reader
// finds them spelled one way: numbers that may be non-finite, and the toolchain fingerprint.
#include <cmath>

#include <nlohmann/json.hpp>

#include "report/Results.h"

namespace shaderbed {

// JSON has no Inf/NaN: a non-finite number is the string "inf", "-inf" or "nan"
// (JsonReport's reader turns them back).
template <class Json = nlohmann::ordered_json>
Json json_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

// {"glslang", "spirv_tools", "spirv_cross", "llvm", "mesa": {"vulkan", "gl"}, "vulkan_device", "gl_platform"}
inline nlohmann::ordered_json json_tools(const ToolVersions& t) {
  return {{"glslang", t.glslang},
          {"spirv_tools", t.spirv_tools},
          {"spirv_cross", t.spirv_cross},
          {"llvm", t.llvm},
          {"mesa", {{"vulkan", t.vulkan_driver}, {"gl", t.gl_driver}}},
          {"vulkan_device", t.vulkan_device},
          {"gl_platform", t.gl_platform}};
}

}  // namespace shaderbed
