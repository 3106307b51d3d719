#include "compile/HlslIntrinsics.h"

#include <vector>

#include "compile/CgTokens.h"

namespace shaderbed {
namespace {

// True when the text declares or defines a function `name` itself ("float4 lit(" ...):
// an identifier other than `return` right before the name and a parenthesis after it.
bool declares_function(const std::vector<cg::Token>& tokens, std::string_view name) {
  for (std::size_t i = 1; i + 1 < tokens.size(); ++i)
    if (tokens[i].is_identifier() && tokens[i].is(name) && tokens[i + 1].is("(") && tokens[i - 1].is_identifier() &&
        !tokens[i - 1].is("return"))
      return true;
  return false;
}

// lit(n.l, n.h, m) = (1, max(n.l, 0), n.l < 0 || n.h < 0 ? 0 : (n.h)^m, 1) (the HLSL
// reference's definition; the same helper as the Cg layer's).
constexpr const char* kLit =
    "float4 shaderbed_hlsl_lit(float NdotL, float NdotH, float m)\n"
    "{\n"
    "    float specular = (NdotL < 0.0 || NdotH < 0.0) ? 0.0 : pow(max(NdotH, 0.0), m);\n"
    "    return float4(1.0, max(NdotL, 0.0), specular, 1.0);\n"
    "}\n"
    "#define lit(NdotL, NdotH, m) shaderbed_hlsl_lit(NdotL, NdotH, m)\n";

// ldexp(x, e) = x * 2^e, for every shape at once (exp2 is component-wise).
constexpr const char* kLdexp = "#define ldexp(x, e) ((x) * exp2(e))\n";

// fmod(x, y) = x - y trunc(x / y): the remainder takes the sign of x. Written inline so it
// takes every shape (x and y are evaluated twice: HLSL arguments with side effects are rare
// enough in shaders not to refuse them).
constexpr const char* kFmod = "#define fmod(x, y) ((x) - (y) * trunc((x) / (y)))\n";

// round(x): the run-time instruction already rounds halves to even, as the HLSL reference
// says; only glslang's constant folder rounds them away from zero. A call through a helper
// is not folded by glslang (spirv-opt folds RoundEven correctly), so literals and run-time
// values round alike.
constexpr const char* kRound =
    "float shaderbed_hlsl_round(float x) { return round(x); }\n"
    "float2 shaderbed_hlsl_round(float2 x) { return round(x); }\n"
    "float3 shaderbed_hlsl_round(float3 x) { return round(x); }\n"
    "float4 shaderbed_hlsl_round(float4 x) { return round(x); }\n"
    "#define round(x) shaderbed_hlsl_round(x)\n";

}  // namespace

std::string hlsl_intrinsic_corrections(std::string_view source_text, HlslIntrinsicSet set) {
  const std::vector<cg::Token> tokens = cg::lex(source_text);
  std::string out;
  if (set.lit && !declares_function(tokens, "lit")) out += kLit;
  if (!declares_function(tokens, "ldexp")) out += kLdexp;
  if (!declares_function(tokens, "fmod")) out += kFmod;
  if (!declares_function(tokens, "round")) out += kRound;
  return out;
}

}  // namespace shaderbed
