#pragma once
#include <string>

#include "core/Error.h"
#include "report/Results.h"

namespace shaderbed {

// JUnit XML for CI: <testsuites> with one <testsuite> per case and one <testcase> per cell
// (classname "case.variant.language", name "backend/path/shape"). A failure is
// <failure message="reason; metrics; attribution: verdict (why)">, a known failure is
// <skipped message="known: reason">, an error is <error message="first line">; every
// testcase has a <system-out> with its timings and image paths. A testcase's time is its
// own stages (build, draw, readback, compare); the compile and reference times, shared by
// cells, are listed in <system-out> only.
std::string to_junit(const RunReport& report);
Result<void> write_junit(const RunReport& report, const std::string& path);

}  // namespace shaderbed
