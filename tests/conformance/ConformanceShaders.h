#pragma once
// The shaders that evaluate the conformance table on the GPU: one program per language,
// one pixel per evaluation. Check k lands on pixel 2k with its arguments as literals (what
// the front end's constant folder computes) and on pixel 2k + 1 with every literal
// multiplied by the uniform One = 1 (what the driver computes at run time; x * 1 is exact).
#include <vector>

#include "IntrinsicChecks.h"
#include "compile/Compiler.h"

namespace shaderbed::conformance {

// Pixels of the image the program draws (two per check; height 2, so every pixel has the
// full 2x2 quad that derivatives need).
int image_width(const std::vector<Check>& checks);
constexpr int kImageHeight = 2;

// Whether check `c` runs through `language` (has a spelling there).
bool runs_in(const Check& c, Language language);

// Vertex and fragment source of the program for `language` (vertex: a pass-through of
// NDC positions; fragment: every check of the language, selected by the pixel's x).
ProgramSource conformance_program(const std::vector<Check>& checks, Language language);

}  // namespace shaderbed::conformance
