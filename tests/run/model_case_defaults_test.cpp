// A model case states only what differs from its model: parameters it leaves out are the
// model's defaults, and without [tolerance] it is judged with the library case's.
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "run/ReferenceKinds.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

Result<Case> completed(const std::string& text) {
  test::TempDir dir("model_case_defaults");
  auto c = load_case(dir.write("mine.toml", text));
  if (!c) return c;
  if (auto ok = complete_case(*c); !ok) return std::unexpected(ok.error());
  return c;
}

TEST(ModelCaseDefaults, ParametersAndTolerancesComeFromTheModel) {
  auto c = completed(R"(model = "blinn_phong"
[params]
power = 20.0
[variants.pixel]
glsl = { vertex = "a.vert", fragment = "a.frag" }
)");
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_EQ(c->params.at("power"), std::vector<double>{20.0});             // the case's own
  EXPECT_EQ(c->params.at("diffuse"), (std::vector<double>{1.0, 1.0, 1.0}));   // the model's default
  EXPECT_EQ(c->interior.max_rel, 0.00014);                                  // blinn_phong.toml's, for power <= 256
  EXPECT_NE(c->interior.reason.find("model blinn_phong's tolerance"), std::string::npos) << c->interior.reason;
  EXPECT_GT(c->silhouette.max_abs, c->interior.max_abs);
}

TEST(ModelCaseDefaults, AStatedToleranceIsKept) {
  auto c = completed(R"(model = "lambert"
[variants.pixel]
glsl = { vertex = "a.vert", fragment = "a.frag" }
[tolerance]
interior = { max_abs = 0.5, reason = "mine" }
silhouette = { max_abs = 0.5, reason = "mine" }
)");
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_EQ(c->interior.max_abs, 0.5);
  EXPECT_EQ(c->interior.reason, "mine");
}

TEST(ModelCaseDefaults, ALutVariantNeedsALutToleranceItsModelHas) {
  auto c = completed(R"(model = "phong"
[variants.pixel_lut]
lut = "warn_power"
glsl = { vertex = "a.vert", fragment = "a.frag" }
)");
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("uses a LUT and model phong has no LUT tolerance"), std::string::npos)
      << c.error().to_string();
}

}  // namespace
}  // namespace shaderbed
