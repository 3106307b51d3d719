#pragma once
// Where a value comes from in the shader's source: the instruction that first computed a
// NaN or infinity at one pixel (with its operands), and the source lines a reduced
// precision touches. Both read the module's OpLine, OpName and OpSource.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "twin/TwinDraw.h"

namespace twin {

struct ValueOrigin {
  std::string file;          // "" when the module carries no lines
  int line = 0;
  std::string source_text;   // that line of the source, trimmed ("" when the module has no text)
  std::string operation;     // "OpFDiv", "GLSL.std.450 Pow"
  std::string result;        // the value's name (OpName) or %id
  std::vector<double> values;
  std::vector<std::pair<std::string, std::vector<double>>> operands;   // name, values
  // "shader.frag:23 `float s = pow(x, y);`: GLSL.std.450 Pow(x = -0.5, y = 1.5) = NaN"
  std::string describe() const;
};

// The fragment stage at pixel (x, y), and the first instruction whose result holds a NaN or
// infinity there; nothing when every value it computes there is finite.
TwinResult<std::optional<ValueOrigin>> first_nonfinite(const DrawInput& input, int x, int y);

// The distinct source lines with an instruction whose result is RelaxedPrecision, in order.
std::vector<SourceLine> relaxed_lines(const Module& module);

// Line `line` of `file`'s text, trimmed, as the module carries it (OpSource) or else as the
// file on disk reads; "" if neither has it.
std::string source_line_text(const Module& module, const std::string& file, int line);

}  // namespace twin
