#pragma once
// The real-world corpus (tests/realworld/) and a quick run of one of its cases: small
// images, two shapes, one worker, no timed repeats.
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "run/Runner.h"

namespace shaderbed::test {

inline const std::filesystem::path kRealWorld = std::filesystem::path(SHADERBED_SOURCE_DIR) / "tests" / "realworld";

inline RunOptions quick_run(const std::string& cases_dir, const std::string& case_name, int size = 48) {
  RunOptions o;
  o.select.cases_dir = cases_dir;
  o.select.cases = {case_name};
  o.select.shapes = {"sphere", "torus"};
  o.cell.size = size;
  o.workers.jobs = 1;
  o.cell.timing = {.warmup = 0, .runs = 0};
  return o;
}

// Expects every cell of the report to have `status`; returns the backend/path pairs seen
// ("vulkan/spirv", "gl/cross", ...), for the test to compare with the paths it expects.
inline std::set<std::string> paths_all_with_status(const RunReport& report, const std::string& status) {
  std::set<std::string> paths;
  for (const CellResult& r : report.results) {
    EXPECT_EQ(to_string(r.status), status) << r.id() << ": " << r.message;
    paths.insert(r.backend + "/" + r.path);
  }
  return paths;
}

}  // namespace shaderbed::test
