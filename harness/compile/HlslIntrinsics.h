#pragma once
// Corrected intrinsics for glslang 12's HLSL front end, found by the intrinsic conformance
// test (tests/conformance): where glslang computes an intrinsic wrongly, or emits SPIR-V
// that spirv-val rejects, the call is routed to a correct implementation written in HLSL.
// The dialect layer of HLSL, beside the Cg one (CgDialect.h), which substitutes its own
// lit() the same way.
//
// The corrections are function-like macros in the preamble, not a token rewrite of the
// file: they then also reach what the file #includes and the effect layer's text, and a
// variable or member named `lit` is untouched (only `lit(` expands). An author's own
// function of the same name is left alone (the macro is not defined).
//
//   lit(n.l, n.h, m)  glslang 12 returns n.h * m as the specular term instead of (n.h)^m
//                     (lit(0.5, 0.5, 4) gave (1, 0.5, 2, 1); the definition is (1, 0.5,
//                     0.0625, 1)), constant-folded and at run time alike.
//   ldexp(x, e)       glslang 12 emits GLSL.std.450 Ldexp with a float exponent, which
//                     spirv-val rejects (the exponent must be an integer): every shader
//                     calling it failed to compile. HLSL defines it as x * 2^e.
//   fmod(x, y)        glslang 12 emits OpFMod, whose result takes the sign of y (GLSL's
//                     mod); HLSL's and Cg's fmod truncate, so the result takes the sign of
//                     x: fmod(-5.5, 2) gave 0.5, the definition is -1.5.
//   round(x)          glslang 12's constant folder rounds halves away from zero (round(2.5)
//                     folded to 3) while the instruction it emits rounds them to even (2,
//                     HLSL's definition): a literal and a uniform of the same value differed.
#include <string>
#include <string_view>

namespace shaderbed {

// Which corrections a front end takes: Cg substitutes lit() in its own layer.
struct HlslIntrinsicSet {
  bool lit = true;
};

// Preamble text (helpers, then macros) for a program whose entry file is `source_text`.
std::string hlsl_intrinsic_corrections(std::string_view source_text, HlslIntrinsicSet set = {});

}  // namespace shaderbed
