#pragma once
// The console view of a bench run: the suite's wall time, where the time went, and the
// reference against the drivers with ratios.
#include <string>

#include "bench/Bench.h"

namespace shaderbed::bench {

std::string bench_table(const BenchReport& report);

}  // namespace shaderbed::bench
