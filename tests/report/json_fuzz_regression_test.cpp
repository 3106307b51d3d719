// Inputs json_report_fuzzer (fuzz/) found crashing the results reader; each is also in
// fuzz/corpus/json_report_fuzzer/ as crash_*. Each must be an error, never an exception.
#include <string>

#include <gtest/gtest.h>

#include "report/JsonReport.h"

namespace shaderbed {
namespace {

// nlohmann::json throws out_of_range (406), not parse_error, for a number beyond double's
// range; parse_json caught only parse_error, so the exception left it.
TEST(JsonFuzzRegression, NumberBeyondDoubleRangeIsAnError) {
  auto report = parse_json(R"({"schema": 2, "wall_ms": 1.8386750169629e948, "results": []})", "overflow.json");
  ASSERT_FALSE(report);
  EXPECT_EQ(report.error().file, "overflow.json");
  EXPECT_NE(report.error().message.find("number overflow"), std::string::npos) << report.error().message;
}

}  // namespace
}  // namespace shaderbed
