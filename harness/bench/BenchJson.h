#pragma once
// The bench run as JSON (schema in docs/timing.md, "shaderbed bench"): the suite's parts
// with their counts and shares, and per compared cell the reference's and each draw's
// median with its interval, and their ratio.
#include <string>

#include "bench/Bench.h"

namespace shaderbed::bench {

constexpr int kBenchSchemaVersion = 1;

std::string bench_json(const BenchReport& report);

}  // namespace shaderbed::bench
