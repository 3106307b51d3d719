#pragma once
// Which cells a merged report covers: the backend x language grid of the union of its parts,
// with each square's cell count, so a CI matrix job that uploaded nothing shows as a hole
// instead of passing unnoticed.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

struct RunCoverage {
  std::vector<std::string> lines;   // "vulkan: hlsl 120, cg 120, glsl 120" per backend
  std::vector<std::string> holes;   // "gl x cg" for each square of the grid with no cell
  size_t cases = 0;                 // distinct cases among the cells
};

RunCoverage run_coverage(const RunReport& report);

}  // namespace shaderbed
