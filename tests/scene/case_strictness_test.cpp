// A case file is read strictly: a typo, a wrong type, a NaN or a name that would leave
// the output folder is an error at its line, never silently ignored.
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

const std::string kGood = R"(model = "lambert"
[params]
diffuse = [1.0, 1.0, 1.0]
[variants.pixel]
hlsl = { vertex = "a.hlsl", fragment = "a.hlsl" }
[tolerance]
interior = { max_abs = 1e-5, reason = "r" }
silhouette = { max_abs = 1e-4, reason = "r" }
)";

// The good case with `from` replaced by `to`, loaded.
Result<Case> load_edited(const std::string& from, const std::string& to, const std::string& file = "c.toml") {
  std::string text = kGood;
  EXPECT_NE(text.find(from), std::string::npos) << from;
  text.replace(text.find(from), from.size(), to);
  test::TempDir dir("strict_case");
  return load_case(dir.write(file, text));
}

TEST(CaseStrictness, TheGoodCaseLoads) { EXPECT_TRUE(load_edited("r\" }\nsilhouette", "r\" }\nsilhouette")); }

TEST(CaseStrictness, AMisspeltTableIsAnErrorWithTheNearestKey) {
  auto c = load_edited("[tolerance]", "[tolerence]");
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("unknown key 'tolerence' in the case (did you mean 'tolerance'?)"), std::string::npos)
      << c.error().to_string();
  EXPECT_EQ(c.error().line, 6);
}

TEST(CaseStrictness, UnknownKeysInATolerance) {
  auto c = load_edited("interior = { max_abs = 1e-5, reason = \"r\" }", "interior = { max_abs = 1e-5, reason = \"r\", mode = 3 }");
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("unknown key 'mode' in tolerance 'interior'"), std::string::npos) << c.error().to_string();
}

TEST(CaseStrictness, NanAndInfAreRefused) {
  auto tol = load_edited("max_abs = 1e-5", "max_abs = nan");
  ASSERT_FALSE(tol);
  EXPECT_NE(tol.error().message.find("max_abs must be a finite number"), std::string::npos) << tol.error().to_string();
  auto param = load_edited("diffuse = [1.0, 1.0, 1.0]", "diffuse = [1.0, inf, 1.0]");
  ASSERT_FALSE(param);
  EXPECT_NE(param.error().message.find("'diffuse' must be finite, not inf"), std::string::npos) << param.error().to_string();
  EXPECT_EQ(param.error().line, 3);
}

TEST(CaseStrictness, WrongTypesAreNamed) {
  auto model = load_edited("model = \"lambert\"", "model = 42");
  ASSERT_FALSE(model);
  EXPECT_NE(model.error().message.find("'model' must be a string"), std::string::npos) << model.error().to_string();
  auto params = load_edited("[params]\ndiffuse = [1.0, 1.0, 1.0]", "params = 5");
  ASSERT_FALSE(params);
  EXPECT_NE(params.error().message.find("'params' must be a table"), std::string::npos) << params.error().to_string();
}

TEST(CaseStrictness, NamesThatWouldLeaveTheOutputFolderAreRefused) {
  auto variant = load_edited("[variants.pixel]", "[variants.\"../../../escaped\"]");
  ASSERT_FALSE(variant);
  EXPECT_NE(variant.error().message.find("variant name '../../../escaped' must be"), std::string::npos)
      << variant.error().to_string();
  auto file = load_edited("model", "model", ".hidden.toml");
  ASSERT_FALSE(file);
  EXPECT_NE(file.error().message.find("case file name '.hidden'"), std::string::npos) << file.error().to_string();
}

}  // namespace
}  // namespace shaderbed
