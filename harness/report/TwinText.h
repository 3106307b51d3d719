#pragma once
// What a cell's twin figures (CellResult::TwinFigures) say, as lines a person reads: the
// console's failure list, JUnit's failure text and the HTML card share them.
#include <string>
#include <vector>

#include "report/Results.h"

namespace shaderbed {

// Nothing for a cell without twin figures.
std::vector<std::string> twin_lines(const CellResult& r);

}  // namespace shaderbed
