#pragma once
// Which parts of an effect file glslang's preprocessor will keep, for the effect layer
// (EffectFile.h), which reads the author's text unpreprocessed (a warm run starts no
// compiler) and must not judge what an #if leaves out: a D3D10 `RasterizerState` or a
// `technique10` under `#if D3D10` is not this effect's when that branch is dropped.
//
// Follows #if, #ifdef, #ifndef, #elif, #else and #endif in order, with the file's own
// object-like #defines and #undefs seen on the way (a function-like macro counts for
// defined() only) and the predefined macros given. An #if expression is C's integer
// expression: defined X, defined(X), numbers, macros expanded, unknown names 0, the
// unary, binary and ?: operators. One it cannot evaluate (a function-like macro call,
// say) keeps every branch of its chain, as the effect layer read them before, with a
// note naming the line: macros from an #include are not seen either.
#include <map>
#include <string>
#include <vector>

#include "compile/CgTokens.h"
#include "compile/EffectFile.h"

namespace shaderbed {

struct ConditionalRegions {
  std::vector<bool> active;         // per token: kept by the preprocessor
  std::vector<EffectNote> notes;    // conditionals the layer could not evaluate
};

ConditionalRegions conditional_regions(const std::vector<cg::Token>& tokens,
                                       const std::map<std::string, std::string>& predefined = {});

}  // namespace shaderbed
