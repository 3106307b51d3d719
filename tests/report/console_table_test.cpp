// The console table: --timing adds the draw's timed repeats and the build time.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "report/ConsoleTable.h"

namespace shaderbed {
namespace {

std::string table_printed(const RunReport& report, const TableOptions& options) {
  char* text = nullptr;
  size_t size = 0;
  std::FILE* out = open_memstream(&text, &size);
  print_table(report, out, options);
  std::fclose(out);
  std::string s(text, size);
  std::free(text);
  return s;
}

RunReport timed_report() {
  RunReport report;
  CellResult built{.case_name = "phong", .variant = "pixel", .language = "glsl", .backend = "vulkan",
                   .path = "spirv", .shape = "sphere", .status = CellStatus::pass};
  built.time_ms["build"] = 61.5;
  built.gpu = {"timestamp queries", 1, 5, {0.75, 0.625, 2.5, 0.9375}, {0.875, 0.8125, 1.0625, 0.9375}};
  CellResult cached = built;
  cached.shape = "cube";
  cached.program_cached = true;
  cached.time_ms["build"] = 0;
  CellResult untimed = built;
  untimed.shape = "cone";
  untimed.gpu = {};
  report.results = {built, cached, untimed};
  return report;
}

TEST(ConsoleTable, TimingColumnsOnlyWhenAsked) {
  const std::string plain = table_printed(timed_report(), {});
  EXPECT_EQ(plain.find("draw ms"), std::string::npos);
  const std::string timed = table_printed(timed_report(), {.timing = true});
  EXPECT_NE(timed.find("draw ms (wall, median [CI])"), std::string::npos) << timed;
  EXPECT_NE(timed.find("0.875 [0.812, 1.062]"), std::string::npos) << timed;   // wall
  EXPECT_NE(timed.find("0.750 [0.625, 2.500]"), std::string::npos) << timed;   // driver clock
  EXPECT_NE(timed.find("61.5"), std::string::npos) << timed;
  EXPECT_NE(timed.find("cached"), std::string::npos) << timed;
  EXPECT_NE(timed.find("docs/timing.md"), std::string::npos) << timed;
}

}  // namespace
}  // namespace shaderbed
