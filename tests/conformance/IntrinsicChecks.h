#pragma once
// The intrinsic conformance table: every HLSL/Cg intrinsic the front ends accept (and its
// GLSL equivalent where GLSL has one), each at sample arguments with its documented
// definition evaluated in double. The shaders that evaluate them on the GPU are written
// from this table (ConformanceShaders.h), so a check and its definition sit side by side.
#include <string>
#include <vector>

#include "pipeline/SamplerSettings.h"
#include "pipeline/Texture.h"

namespace shaderbed::conformance {

// One argument: a scalar (1x1), a vector (1xN) or a matrix (RxC, row-major as HLSL writes
// it). Values are floats (rounded when the check is made), held in double.
struct Arg {
  int rows = 1;
  int cols = 1;
  std::vector<double> v;
};

// Which front ends a check runs through. HLSL and Cg share a spelling; GLSL has its own.
enum LanguageMask : unsigned { kHlsl = 1, kCg = 2, kGlsl = 4, kHlslCg = kHlsl | kCg, kAll = kHlsl | kCg | kGlsl };

struct Check {
  std::string intrinsic;     // what the report names: "lit", "mul(float4, float4x4)"
  std::vector<Arg> args;
  // The expression, $0 $1 ... standing for the arguments; empty = not in that language.
  // The expression yields up to 4 floats (a matrix result is checked one row per Check).
  std::string hlsl_cg;
  std::string glsl;
  unsigned languages = kAll;
  std::vector<double> expected;  // the documented definition, in double
  // Allowed |gpu - expected| <= tolerance * max(1, |expected|, scale); the scale is the
  // largest argument magnitude (0: computed from the arguments) for results that cancel.
  double tolerance = 1e-6;
  double scale = 0;
  // Evaluated before the per-pixel selection, in uniform control flow: derivatives and
  // implicit-LOD lookups are undefined inside a branch that neighbouring pixels skip.
  bool uniform_flow = false;
  // Arguments are written as literals only (positions, samplers): no runtime variant.
  bool literal_only = false;
};

// Every check, in a fixed order (the pixel a check lands on is its index).
const std::vector<Check>& intrinsic_checks();

// The texture the lookups sample, bound as "Tex": kTextureSize square with its full mip
// chain, texel (x, y) of level L = (x, y, L, 1); sampled nearest, nearest mip, clamped.
constexpr int kTextureSize = 4;
Texture conformance_texture();
SamplerSettings conformance_sampler();

// "(0.5, float3(1, 0, -1))": the arguments as a report prints them.
std::string describe_args(const std::vector<Arg>& args);

}  // namespace shaderbed::conformance
