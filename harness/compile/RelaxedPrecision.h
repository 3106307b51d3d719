#pragma once
// The precision sweep axis: the same shader with its floating point declared relaxed, so
// glslang decorates the arithmetic RelaxedPrecision (SPIR-V's "may be evaluated at 16 bits
// or more") and a driver that lowers it to fp16 may. GLSL gets `precision mediump float;`
// after #version; HLSL and Cg get the float types #defined to HLSL's min16float family,
// which glslang maps to 32-bit floats decorated RelaxedPrecision. Error lines keep their
// numbers (#line).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "compile/Compiler.h"
#include "core/Error.h"

namespace shaderbed {

Result<ShaderSource> relax_precision(Language language, ShaderSource source);

// How many RelaxedPrecision decorations a module has, on ids and struct members alike (a port
// notes those its target drops).
size_t relaxed_precision_decorations(std::span<const uint32_t> spirv);

}  // namespace shaderbed
