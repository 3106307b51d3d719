// Differential cases: `reference = { ... }` instead of a model, read strictly, with the
// documented fp32 tolerance when the case states none.
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

const std::string kGoodDifferential = R"(reference = { language = "hlsl", backend = "vulkan" }
[variants.pixel]
hlsl = { vertex = "a.hlsl", fragment = "a.hlsl" }
glsl = { vertex = "a.vert", fragment = "a.frag" }
)";

Result<Case> load_differential(const std::string& from, const std::string& to) {
  std::string text = kGoodDifferential;
  EXPECT_NE(text.find(from), std::string::npos) << from;
  text.replace(text.find(from), from.size(), to);
  test::TempDir dir("differential_case");
  return load_case(dir.write("c.toml", text));
}

std::string message(const Result<Case>& c) { return c ? std::string("(loaded)") : c.error().to_string(); }

TEST(DifferentialCase, LoadsWithTheDocumentedDefaults) {
  auto c = load_differential("a.hlsl", "a.hlsl");
  ASSERT_TRUE(c) << message(c);
  EXPECT_TRUE(c->differential());
  ASSERT_TRUE(c->reference_render);
  EXPECT_EQ(c->reference_render->language, Language::hlsl);
  EXPECT_EQ(c->reference_render->backend, "vulkan");
  EXPECT_EQ(c->reference_render->path, "spirv");
  EXPECT_EQ(c->interior.max_rel, 0x1p-13);
  EXPECT_NE(c->interior.reason.find("differential default"), std::string::npos);
  EXPECT_GT(c->silhouette.max_rel, c->interior.max_rel);
}

TEST(DifferentialCase, GlslOnGlDefaultsToTheNativePath) {
  auto c = load_differential("language = \"hlsl\", backend = \"vulkan\"", "language = \"glsl\", backend = \"gl\"");
  ASSERT_TRUE(c) << message(c);
  EXPECT_EQ(c->reference_render->path, "glsl");
}

TEST(DifferentialCase, ACaseMayStateItsOwnToleranceWithAReason) {
  auto c = load_differential("glsl = { vertex = \"a.vert\", fragment = \"a.frag\" }\n",
                       "glsl = { vertex = \"a.vert\", fragment = \"a.frag\" }\n[tolerance]\n"
                       "interior = { max_abs = 1e-4, max_rel = 1e-3, reason = \"a tone map's exp\" }\n"
                       "silhouette = { max_abs = 1e-3, reason = \"edges\" }\n");
  ASSERT_TRUE(c) << message(c);
  EXPECT_EQ(c->interior.max_abs, 1e-4);
  EXPECT_EQ(c->interior.max_rel, 1e-3);
  EXPECT_EQ(c->interior.reason, "a tone map's exp");
  EXPECT_EQ(c->silhouette.max_rel, 0.0);
}

TEST(DifferentialCase, StoredImagesResolveFromTheCaseFolder) {
  auto c = load_differential("reference = { language = \"hlsl\", backend = \"vulkan\" }", "reference = { images = \"good\" }");
  ASSERT_TRUE(c) << message(c);
  EXPECT_TRUE(c->reference_images.ends_with("/good"));
  EXPECT_FALSE(c->reference_render);
}

TEST(DifferentialCase, BadReferencesAreErrorsAtTheirLine) {
  const std::pair<std::string, std::string> bad[] = {
      {"reference = { language = \"hlsl\", backend = \"vulkan\" }",
       "model = \"lambert\"\nreference = { language = \"hlsl\" }"},   // both
      {"backend = \"vulkan\"", "backend = \"metal\""},
      {"backend = \"vulkan\"", "backend = \"vulkan\", path = \"cross\""},
      {"backend = \"vulkan\"", "backend = \"gl\", path = \"glsl\""},   // HLSL has no native GL path
      {"language = \"hlsl\"", "language = \"cg\""},                      // no cg shaders
      {"backend = \"vulkan\"", "backend = \"vulkan\", variant = \"vertex\""},
      {"backend = \"vulkan\" }", "backend = \"vulkan\", pth = \"spirv\" }"},
      {"reference = { language = \"hlsl\", backend = \"vulkan\" }", "reference = { images = \"x\", language = \"hlsl\" }"},
      {"reference = { language = \"hlsl\", backend = \"vulkan\" }", ""},   // neither model nor reference
  };
  const char* expected[] = {"either a model or a reference", "must be \"vulkan\" or \"gl\"", "only path = \"spirv\"",
                            "native GL path of GLSL", "has no cg shaders", "'vertex' is not a variant",
                            "did you mean 'path'", "takes no language", "missing 'model'"};
  for (size_t i = 0; i < std::size(bad); ++i) {
    auto c = load_differential(bad[i].first, bad[i].second);
    ASSERT_FALSE(c) << bad[i].second;
    EXPECT_NE(c.error().message.find(expected[i]), std::string::npos) << c.error().to_string();
    EXPECT_EQ(c.error().stage, ErrorStage::case_file);
  }
}

TEST(DifferentialCase, AModelCaseWithoutTolerancesLeavesThemToItsModel) {
  auto c = load_differential("reference = { language = \"hlsl\", backend = \"vulkan\" }", "model = \"lambert\"");
  ASSERT_TRUE(c) << message(c);
  EXPECT_FALSE(c->differential());
  EXPECT_TRUE(c->tolerance_from_model);
}

TEST(DifferentialCase, AnOriginalNamedByLanguageAloneIsJudgedByItsDoubleTwin) {
  auto c = load_differential("language = \"hlsl\", backend = \"vulkan\"", "language = \"hlsl\"");
  ASSERT_TRUE(c) << message(c);
  EXPECT_EQ(c->reference_render->backend, "twin-double");
  EXPECT_EQ(c->reference_render->path, "spirv");
}

TEST(DifferentialCase, TwinNamesThePrecisionAndTakesNoBackend) {
  auto twin_float = load_differential("backend = \"vulkan\"", "twin = \"float\"");
  ASSERT_TRUE(twin_float) << message(twin_float);
  EXPECT_EQ(twin_float->reference_render->backend, "twin-float");
  auto both = load_differential("backend = \"vulkan\"", "backend = \"vulkan\", twin = \"double\"");
  ASSERT_FALSE(both);
  EXPECT_NE(both.error().message.find("takes no backend"), std::string::npos) << both.error().message;
  auto unknown = load_differential("backend = \"vulkan\"", "twin = \"quad\"");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("\"double\", \"float\" or \"half\""), std::string::npos) << unknown.error().message;
}

}  // namespace
}  // namespace shaderbed
