#pragma once
// Known failures, as deqp-runner's baselines: a TOML file of cell patterns, each with a
// reason. A matching failure is reported as known (the run still passes); a new failure
// fails the run; a known failure that now passes is reported so the entry can go.
//
//   [[known]]
//   cells = "warn/pixel/*/gl/*/torus"      # case/variant/language/backend/path/shape, * = any
//   reason = "llvmpipe's pow differs ... (Mesa 22.3)"
#include <string>
#include <vector>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

struct KnownFailure {
  std::string pattern;
  std::string reason;
  int line = 0;
};

Result<std::vector<KnownFailure>> load_expectations(const std::string& path);

bool matches(const std::string& pattern, const std::string& cell_id);

// Marks known failures; returns the ids of known failures that passed.
std::vector<std::string> apply_expectations(const std::vector<KnownFailure>& known, RunReport& report);

}  // namespace shaderbed
