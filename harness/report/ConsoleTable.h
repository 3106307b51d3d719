#pragma once
#include <cstdio>

#include "report/Results.h"

namespace shaderbed {

// The aligned result table, then a line per failure or error, then the totals.
void print_table(const RunReport& report, std::FILE* out);

}  // namespace shaderbed
