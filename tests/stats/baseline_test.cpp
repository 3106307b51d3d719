// shader-db style comparison on two synthetic stats files.
#include <gtest/gtest.h>

#include "stats/Baseline.h"
#include "stats/StatsReport.h"

namespace shaderbed::stats {
namespace {

StatsReport report(const std::vector<std::pair<std::string, int>>& shaders) {
  StatsReport r;
  for (const auto& [name, total] : shaders) {
    StatsEntry e{.case_name = name, .variant = "pixel", .language = "glsl", .stage = "fragment"};
    e.spirv_opt.total = e.spirv_opt.arithmetic = total;
    r.entries.push_back(e);
  }
  return r;
}

// a 100->90 (-10%), b 50->40 (-20%), c 10->12 (+20%), d 20->30 (+50%), e unchanged,
// lost: f; gained: g.
const StatsReport kOld = report({{"a", 100}, {"b", 50}, {"c", 10}, {"d", 20}, {"e", 7}, {"f", 3}});
const StatsReport kNew = report({{"a", 90}, {"b", 40}, {"c", 12}, {"d", 30}, {"e", 7}, {"g", 5}});

TEST(Baseline, HelpedAndHurtSortedByRelativeChange) {
  const Comparison c = compare(kOld, kNew);
  ASSERT_EQ(c.helped.size(), 2u);
  EXPECT_EQ(c.helped[0].key, "b/pixel/glsl/fragment");   // -20% before -10%
  EXPECT_EQ(c.helped[1].key, "a/pixel/glsl/fragment");
  ASSERT_EQ(c.hurt.size(), 2u);
  EXPECT_EQ(c.hurt[0].key, "d/pixel/glsl/fragment");     // +50% before +20%
  EXPECT_EQ(c.hurt[1].key, "c/pixel/glsl/fragment");
  EXPECT_EQ(c.unchanged, 1);
  EXPECT_EQ(c.total_before, 187);
  EXPECT_EQ(c.total_after, 179);
  EXPECT_EQ(c.affected_before, 180);
  EXPECT_EQ(c.affected_after, 172);
  EXPECT_EQ(c.lost, std::vector<std::string>{"f/pixel/glsl/fragment"});
  EXPECT_EQ(c.gained, std::vector<std::string>{"g/pixel/glsl/fragment"});
  const std::string text = format_comparison(c);
  EXPECT_LT(text.find("helped:   b/"), text.find("helped:   a/"));
  EXPECT_LT(text.find("HURT:     d/"), text.find("HURT:     c/"));
  EXPECT_NE(text.find("LOST:   1 shaders"), std::string::npos);
  EXPECT_NE(text.find("GAINED: 1 shaders"), std::string::npos);
}

// Diffs -10, -10, +2, +10: mean -2, sd = sqrt(((-8)^2 + (-8)^2 + 4^2 + 12^2) / 3) = sqrt(96),
// half width = t(3) 3.182 * sqrt(96) / 2 = 15.589: [-17.59, 13.59] includes 0.
TEST(Baseline, ConfidenceIntervalAndInconclusive) {
  const Comparison c = compare(kOld, kNew);
  ASSERT_TRUE(c.mean_ci.has_value());
  EXPECT_DOUBLE_EQ(c.mean_change, -2.0);
  // Half-width t(0.975, 1) x s / sqrt(n), with t = 12.7062 exactly (12.706 in printed tables).
  EXPECT_NEAR(c.mean_ci->low, -2.0 - 15.5907, 1e-3);
  EXPECT_NEAR(c.mean_ci->high, -2.0 + 15.5907, 1e-3);
  EXPECT_TRUE(c.inconclusive());
  EXPECT_NE(format_comparison(c).find("Inconclusive result"), std::string::npos);
}

// Every shader 10% smaller, give or take one: a conclusive improvement.
TEST(Baseline, ConclusiveWhenIntervalExcludesZero) {
  const Comparison c = compare(report({{"a", 100}, {"b", 100}, {"c", 100}}), report({{"a", 90}, {"b", 89}, {"c", 91}}));
  ASSERT_TRUE(c.mean_ci.has_value());
  EXPECT_LT(c.mean_ci->high, 0);
  EXPECT_FALSE(c.inconclusive());
  EXPECT_NE(format_comparison(c).find("are helped."), std::string::npos);
}

TEST(Baseline, FailAboveIsTheAffectedTotal) {
  // Affected: 180 -> 172 (-4.4%): no threshold is crossed.
  EXPECT_FALSE(exceeds(compare(kOld, kNew), 0));
  // Reversed: 172 -> 180 (+4.65%).
  const Comparison worse = compare(kNew, kOld);
  EXPECT_NEAR(worse.affected_percent(), 100.0 * 8 / 172, 1e-9);
  EXPECT_TRUE(exceeds(worse, 4.0));
  EXPECT_FALSE(exceeds(worse, 5.0));
}

TEST(Baseline, JsonRoundTripKeepsTheSchema) {
  StatsReport r = kOld;
  r.tool = {{"glslang", "12"}};
  r.entries[0].book = 46;
  r.entries[0].spirv.extended_calls = {{"Pow", 2}};
  auto back = from_json(to_json(r));
  ASSERT_TRUE(back.has_value()) << back.error().to_string();
  ASSERT_EQ(back->entries.size(), r.entries.size());
  EXPECT_EQ(back->entries[0].book, 46);
  EXPECT_FALSE(back->entries[0].nir.has_value());
  EXPECT_EQ(back->entries[0].spirv, r.entries[0].spirv);
  EXPECT_EQ(back->tool.at("glslang"), "12");
  const std::string json = to_json(r);
  EXPECT_NE(json.find("\"nir\": null"), std::string::npos);
  EXPECT_NE(json.find("\"book\": null"), std::string::npos);
}

TEST(Baseline, TCritical) {
  EXPECT_NEAR(t_critical_95(1), 12.706, 5e-4);   // the printed tables' values
  EXPECT_NEAR(t_critical_95(5), 2.571, 5e-4);
  EXPECT_NEAR(t_critical_95(30), 2.042, 5e-4);
  EXPECT_NEAR(t_critical_95(60), 2.000, 5e-4);
  EXPECT_NEAR(t_critical_95(1000000), 1.960, 1e-3);
}

}  // namespace
}  // namespace shaderbed::stats
