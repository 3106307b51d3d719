// --param parsing and application to the selected cases.
#include <gtest/gtest.h>

#include "run/ParameterOverrides.h"

namespace shaderbed {
namespace {

TEST(ParameterOverrides, ParsesScalarsAndLists) {
  auto p = parse_parameter("power=20");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->first, "power");
  EXPECT_EQ(p->second, std::vector<double>{20});
  auto list = parse_parameter("diffuse=1,0.5,-2e-3");
  ASSERT_TRUE(list);
  EXPECT_EQ(list->second, (std::vector<double>{1, 0.5, -2e-3}));
  for (const char* bad : {"power", "=3", "power=", "power=abc", "power=1,,2", "power=1x", "power=nan", "power=inf", "d=1,-inf,0"})
    EXPECT_FALSE(parse_parameter(bad)) << bad;
}

TEST(ParameterOverrides, AppliesOnlyToSelectedCasesThatHaveIt) {
  std::vector<Case> cases(2);
  cases[0].name = "phong";
  cases[0].params = {{"power", {7}}, {"diffuse", {1, 1, 1}}};
  cases[1].name = "blinn";
  cases[1].params = {{"power", {7}}};
  ASSERT_TRUE(apply_parameter_overrides({"power=30"}, {"phong"}, cases));
  EXPECT_EQ(cases[0].params["power"], std::vector<double>{30});
  EXPECT_EQ(cases[1].params["power"], std::vector<double>{7});
  auto unknown = apply_parameter_overrides({"roughness=0.1"}, {}, cases);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("roughness"), std::string::npos);
  EXPECT_FALSE(apply_parameter_overrides({"diffuse=1,2"}, {}, cases)) << "wrong value count";
}

}  // namespace
}  // namespace shaderbed
