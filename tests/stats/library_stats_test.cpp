// On the shader library: LUT variants cost fewer arithmetic instructions than their
// arithmetic twins after spirv-opt -O (the book's direction: Oren-Nayar 70 -> 27, Ward 51 -> 19).
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "stats/Collect.h"

namespace shaderbed::stats {
namespace {

const std::string kCases = (std::filesystem::path(SHADERBED_SOURCE_DIR) / "shaders" / "cases").string();

TEST(LibraryStats, LutVariantsCountFewerArithmetic) {
  for (const char* name : {"oren_nayar", "ward_iso"}) {
    auto report = collect_stats({.cases_dir = kCases, .cases = {name}, .variants = {"pixel", "pixel_lut"}});
    ASSERT_TRUE(report.has_value()) << report.error().to_string();
    std::map<std::string, std::map<std::string, const StatsEntry*>> fragment;   // language -> variant
    for (const StatsEntry& e : report->entries) {
      EXPECT_EQ(e.error, "") << e.key();
      if (e.stage == "fragment") fragment[e.language][e.variant] = &e;
    }
    EXPECT_EQ(fragment.size(), 3u) << name;   // hlsl, cg, glsl side by side
    for (const auto& [language, v] : fragment) {
      ASSERT_TRUE(v.contains("pixel") && v.contains("pixel_lut")) << name << " " << language;
      const int plain = v.at("pixel")->spirv_opt.arithmetic + v.at("pixel")->spirv_opt.extended;
      const int lut = v.at("pixel_lut")->spirv_opt.arithmetic + v.at("pixel_lut")->spirv_opt.extended;
      EXPECT_LT(v.at("pixel_lut")->spirv_opt.arithmetic, v.at("pixel")->spirv_opt.arithmetic) << name << " " << language;
      EXPECT_LT(lut, plain) << name << " " << language;
      EXPECT_GE(v.at("pixel_lut")->spirv_opt.texture, 1) << name << " " << language;
      EXPECT_EQ(v.at("pixel")->book.has_value(), true) << name;
    }
  }
}

}  // namespace
}  // namespace shaderbed::stats
