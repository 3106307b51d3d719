// Attribution on a full synthetic matrix of renders (3 languages x their backend/path
// combinations, as the runner produces them), each a real image compared with the
// reference by compare_images: one broken stage at a time must be named.
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestThresholds.h"
#include "CompareTestSupport.h"
#include "compare/Attribution.h"

namespace shaderbed {
namespace {

using namespace compare_test;
using test::kThresholds;

struct Cell {
  std::string language, backend, path;
  std::string id() const { return language + " " + backend + "/" + path; }
};

// The runner's matrix: GLSL on Vulkan (SPIR-V) and GL (native, SPIR-V, cross); HLSL
// and Cg on Vulkan (SPIR-V) and GL (SPIR-V, cross).
const std::vector<Cell>& matrix() {
  static const std::vector<Cell> cells{
      {"glsl", "vulkan", "spirv"}, {"glsl", "gl", "glsl"},  {"glsl", "gl", "spirv"}, {"glsl", "gl", "cross"},
      {"hlsl", "vulkan", "spirv"}, {"hlsl", "gl", "spirv"}, {"hlsl", "gl", "cross"}, {"cg", "vulkan", "spirv"},
      {"cg", "gl", "spirv"},       {"cg", "gl", "cross"},
  };
  return cells;
}

struct Group {
  ReferenceImage reference = disc_reference();
  std::vector<Image> images;
  std::vector<RenderOutcome> outcomes;
  std::vector<Verdict> verdicts;

  // Every cell renders `good` unless `broken` gives it another image.
  Group(const Image& good, const std::map<std::string, Image>& broken, double expected_area = 0,
        ReferenceImage ref = disc_reference()) : reference(std::move(ref)) {
    images.reserve(matrix().size());
    for (const Cell& c : matrix()) {
      auto b = broken.find(c.id());
      images.push_back(b == broken.end() ? good : b->second);
    }
    for (size_t i = 0; i < matrix().size(); ++i) {
      const Cell& c = matrix()[i];
      const bool pass = compare_images(images[i], reference, kThresholds, expected_area).pass;
      outcomes.push_back({c.language, c.backend, c.path, pass, &images[i]});
    }
    verdicts = attribute_failures(outcomes, reference, kThresholds, expected_area);
  }

  const Verdict& of(const std::string& id) const {
    for (size_t i = 0; i < matrix().size(); ++i)
      if (matrix()[i].id() == id) return verdicts[i];
    throw std::runtime_error("no cell " + id);
  }
  bool passes(const std::string& id) const {
    for (size_t i = 0; i < matrix().size(); ++i)
      if (matrix()[i].id() == id) return outcomes[i].pass;
    throw std::runtime_error("no cell " + id);
  }
};

Image good() { return copy_of(disc_reference()); }
// Two different wrong shadings (a flipped-sign-like offset and a scale).
Image wrong() { return disc_render(20, 32, 32, kSize, [](double v, int) { return v + 0.1; }); }
Image other_wrong() { return disc_render(20, 32, 32, kSize, [](double v, int) { return v * 0.5; }); }

std::map<std::string, Image> broken(const std::vector<std::string>& ids, const Image& image) {
  std::map<std::string, Image> m;
  for (const std::string& id : ids) m.emplace(id, image);
  return m;
}

TEST(Attribution, AllPassingHasNoVerdicts) {
  const Group g(good(), {});
  for (size_t i = 0; i < g.verdicts.size(); ++i) {
    EXPECT_TRUE(g.outcomes[i].pass);
    EXPECT_EQ(g.verdicts[i].attribution, Attribution::none);
    EXPECT_EQ(g.verdicts[i].reason, "");
    EXPECT_STREQ(to_string(g.verdicts[i].attribution), "");
  }
}

TEST(Attribution, OneLanguageFailingEverywhereIsTheFrontEnd) {
  const Group g(good(), broken({"glsl vulkan/spirv", "glsl gl/glsl", "glsl gl/spirv", "glsl gl/cross"}, wrong()));
  for (const Cell& c : matrix()) {
    const Verdict& v = g.of(c.id());
    if (c.language == "glsl") {
      EXPECT_EQ(v.attribution, Attribution::front_end) << c.id() << ": " << v.reason;
      EXPECT_EQ(v.reason, "glsl renders on all 4 paths (vulkan/spirv, gl/glsl, gl/spirv, gl/cross) differ from the "
                          "reference and agree with each other (max difference 0); hlsl and cg pass");
    } else {
      EXPECT_EQ(v.attribution, Attribution::none) << c.id();
    }
  }
  EXPECT_STREQ(to_string(Attribution::front_end), "front end");
}

TEST(Attribution, OnlyTheCrossPathFailingIsTheCrossCompiler) {
  const Group g(good(), broken({"hlsl gl/cross"}, wrong()));
  const Verdict& v = g.of("hlsl gl/cross");
  EXPECT_EQ(v.attribution, Attribution::cross_compiler) << v.reason;
  EXPECT_EQ(v.reason, "hlsl on gl/cross differs from the reference; hlsl on vulkan/spirv, gl/spirv pass");
  EXPECT_STREQ(to_string(v.attribution), "cross-compiler");

  // The same SPIRV-Cross fault in every language: still the cross-compiler for each.
  const Group all(good(), broken({"glsl gl/cross", "hlsl gl/cross", "cg gl/cross"}, wrong()));
  for (const char* id : {"glsl gl/cross", "hlsl gl/cross", "cg gl/cross"}) {
    EXPECT_EQ(all.of(id).attribution, Attribution::cross_compiler) << id << ": " << all.of(id).reason;
    EXPECT_NE(all.of(id).reason.find("the cross path also fails for"), std::string::npos) << all.of(id).reason;
  }
}

TEST(Attribution, OneBackendFailingIsTheDriver) {
  // GL gets every language wrong (all paths); Vulkan renders the same shaders right.
  std::vector<std::string> gl_cells;
  for (const Cell& c : matrix())
    if (c.backend == "gl") gl_cells.push_back(c.id());
  const Group g(good(), broken(gl_cells, wrong()));
  for (const Cell& c : matrix()) {
    const Verdict& v = g.of(c.id());
    if (c.backend == "gl") {
      EXPECT_EQ(v.attribution, Attribution::driver) << c.id() << ": " << v.reason;
      EXPECT_NE(v.reason.find(c.language + " on gl/" + c.path + " differs from the reference; the same " + c.language +
                              " shaders pass on vulkan (vulkan/spirv); also failing on gl:"),
                std::string::npos)
          << v.reason;
    } else {
      EXPECT_EQ(v.attribution, Attribution::none);
    }
  }
  EXPECT_STREQ(to_string(Attribution::driver), "driver");
}

TEST(Attribution, OneDriverPathFailingIsTheDriver) {
  // GL's SPIR-V consumer mishandles the GLSL shader; its native and cross GLSL work.
  const Group g(good(), broken({"glsl gl/spirv"}, wrong()));
  const Verdict& v = g.of("glsl gl/spirv");
  EXPECT_EQ(v.attribution, Attribution::driver) << v.reason;
  EXPECT_EQ(v.reason, "glsl on gl/spirv differs from the reference; the same glsl shaders pass on vulkan "
                      "(vulkan/spirv); every other gl render passes");
  // Vulkan failing for one language while GL passes it on every path.
  const Group vk(good(), broken({"cg vulkan/spirv"}, wrong()));
  EXPECT_EQ(vk.of("cg vulkan/spirv").attribution, Attribution::driver) << vk.of("cg vulkan/spirv").reason;
  EXPECT_NE(vk.of("cg vulkan/spirv").reason.find("pass on gl (gl/spirv, gl/cross)"), std::string::npos);
}

TEST(Attribution, AllRendersAgreeingAgainstTheReferenceIsTheModel) {
  // Every render is right by the shaders' own standard; the reference is not.
  ReferenceImage wrong_reference = disc_reference();
  for (size_t i = 0; i < wrong_reference.coverage.size(); ++i)
    if (wrong_reference.coverage[i]) wrong_reference.rgba[i * 4] += 0.2;
  // Small fp32-like differences between the routes stay within the threshold.
  std::map<std::string, Image> routes;
  routes.emplace("hlsl gl/cross", disc_render(20, 32, 32, kSize, [](double v, int) { return v + 3e-6; }));
  const Group g(good(), routes, 0, wrong_reference);
  for (const Cell& c : matrix()) {
    const Verdict& v = g.of(c.id());
    EXPECT_FALSE(g.passes(c.id()));
    EXPECT_EQ(v.attribution, Attribution::model_reference) << c.id() << ": " << v.reason;
    EXPECT_EQ(v.reason.rfind("all 10 renders (glsl, hlsl, cg on vulkan, gl) agree with each other (max difference ", 0),
              0u)
        << v.reason;
    EXPECT_NE(v.reason.find("<= 1e-05) but not with the reference"), std::string::npos) << v.reason;
  }
  EXPECT_STREQ(to_string(Attribution::model_reference), "model/reference");
}

TEST(Attribution, AReferenceOfTheWrongSizeIsTheModelAndAMatchingOneIsNot) {
  // The reference drew the shape 30 % too large; every render has the expected area.
  const double expected = disc_area(20);
  const Group g(good(), {}, expected, disc_reference(26));
  EXPECT_EQ(g.of("glsl vulkan/spirv").attribution, Attribution::model_reference) << g.of("glsl vulkan/spirv").reason;
  // Every render drew the shape too large the same way while the reference matches
  // the mesh's area: the renders share a fault; the reference is vindicated.
  const Image big = disc_render(26);
  std::map<std::string, Image> all;
  for (const Cell& c : matrix()) all.emplace(c.id(), big);
  const Group v(good(), all, expected);
  const Verdict& verdict = v.of("hlsl gl/spirv");
  EXPECT_EQ(verdict.attribution, Attribution::unclear) << verdict.reason;
  EXPECT_NE(verdict.reason.find("which the reference"), std::string::npos) << verdict.reason;
  EXPECT_NE(verdict.reason.find("not the model"), std::string::npos) << verdict.reason;
}

TEST(Attribution, AllFailingButDisagreeingIsUnclear) {
  std::map<std::string, Image> m;
  for (const Cell& c : matrix()) m.emplace(c.id(), c.language == "cg" ? other_wrong() : wrong());
  const Group g(good(), m);
  for (const Cell& c : matrix()) {
    EXPECT_EQ(g.of(c.id()).attribution, Attribution::unclear);
    EXPECT_NE(g.of(c.id()).reason.find("disagree with each other"), std::string::npos) << g.of(c.id()).reason;
  }
}

TEST(Attribution, OneLanguageOnlyCannotBlameTheModel) {
  const ReferenceImage ref = disc_reference();
  const Image w = wrong();
  const std::vector<RenderOutcome> rs{{"glsl", "vulkan", "spirv", false, &w}, {"glsl", "gl", "glsl", false, &w}};
  const auto v = attribute_failures(rs, ref, kThresholds);
  EXPECT_EQ(v[0].attribution, Attribution::unclear);
  EXPECT_NE(v[0].reason.find("one language"), std::string::npos) << v[0].reason;
}

TEST(Attribution, MixedPatternIsUnclear) {
  // GLSL fails on Vulkan and on GL's native path but passes GL's SPIR-V and cross paths:
  // no single stage is shared by exactly the failing renders.
  const Group g(good(), broken({"glsl vulkan/spirv", "glsl gl/glsl"}, wrong()));
  for (const char* id : {"glsl vulkan/spirv", "glsl gl/glsl"}) {
    EXPECT_EQ(g.of(id).attribution, Attribution::unclear) << g.of(id).reason;
    EXPECT_EQ(g.of(id).reason.rfind("no single stage explains it: failing glsl vulkan/spirv, glsl gl/glsl; passing glsl "
                                    "gl/spirv",
                                    0),
              0u)
        << g.of(id).reason;
  }
  EXPECT_STREQ(to_string(Attribution::unclear), "unclear");
}

TEST(Attribution, FrontEndRendersThatDisagreeAreStillTheFrontEndButSaySo) {
  const Group g(good(), {{"cg vulkan/spirv", wrong()}, {"cg gl/spirv", other_wrong()}, {"cg gl/cross", wrong()}});
  const Verdict& v = g.of("cg gl/spirv");
  EXPECT_EQ(v.attribution, Attribution::front_end) << v.reason;
  EXPECT_NE(v.reason.find("(and differ from each other: max difference"), std::string::npos) << v.reason;
  EXPECT_NE(v.reason.find("glsl and hlsl pass"), std::string::npos) << v.reason;
}

TEST(Attribution, OneBackendOnlyStillSeesTheFrontEnd) {
  // A run filtered to Vulkan: one render per language.
  const ReferenceImage ref = disc_reference();
  const Image g = good(), w = wrong();
  const std::vector<RenderOutcome> rs{{"glsl", "vulkan", "spirv", true, &g}, {"hlsl", "vulkan", "spirv", false, &w}};
  const auto v = attribute_failures(rs, ref, kThresholds);
  EXPECT_EQ(v[0].attribution, Attribution::none);
  EXPECT_EQ(v[1].attribution, Attribution::front_end);
  EXPECT_EQ(v[1].reason, "hlsl render on its only path (vulkan/spirv) differs from the reference; glsl passes");
}

TEST(RendersMaxDifference, OverTheReferenceInterior) {
  const ReferenceImage ref = disc_reference();
  const auto classes = classify_pixels(ref);
  Image a = copy_of(ref), b = copy_of(ref);
  std::vector<const Image*> both{&a, &b};
  EXPECT_EQ(renders_max_difference(both, classes), 0.0);
  b.pixel(32, 32)[1] += 0.25f;
  EXPECT_NEAR(renders_max_difference(both, classes), 0.25, 1e-6);
  b.pixel(0, 0)[0] = 100;   // background: not looked at
  EXPECT_NEAR(renders_max_difference(both, classes), 0.25, 1e-6);
  a.pixel(30, 30)[2] = b.pixel(30, 30)[2] = std::numeric_limits<float>::quiet_NaN();   // the same NaN: agreement
  EXPECT_NEAR(renders_max_difference(both, classes), 0.25, 1e-6);
  b.pixel(31, 30)[2] = std::numeric_limits<float>::quiet_NaN();   // NaN against a number
  EXPECT_EQ(renders_max_difference(both, classes), std::numeric_limits<double>::infinity());
  Image c = copy_of(ref);
  c.coverage[size_t(32) * kSize + 32] = 0;   // one interior pixel not drawn
  std::vector<const Image*> cover{&a, &c};
  a.pixel(30, 30)[2] = c.pixel(30, 30)[2];
  EXPECT_EQ(renders_max_difference(cover, classes), std::numeric_limits<double>::infinity());
  std::vector<const Image*> one{&a};
  EXPECT_EQ(renders_max_difference(one, classes), 0.0);
}

}  // namespace
}  // namespace shaderbed

namespace shaderbed {
namespace {

// A GLSL ES mediump shader: gl/glsl computes it in reduced precision, the others in full.
std::vector<Verdict> mediump_group(const Image& native, const Image& others, bool native_reduced) {
  static const ReferenceImage reference = disc_reference();
  static std::vector<Image> images;
  images = {others, native, others, others};
  std::vector<RenderOutcome> outcomes;
  const char* paths[][2] = {{"vulkan", "spirv"}, {"gl", "glsl"}, {"gl", "spirv"}, {"gl", "cross"}};
  for (size_t i = 0; i < 4; ++i)
    outcomes.push_back({"glsl", paths[i][0], paths[i][1], compare_images(images[i], reference, kThresholds).pass,
                        &images[i], native_reduced && i == 1});
  return attribute_failures(outcomes, reference, kThresholds);
}

TEST(Attribution, OnlyThePathThatComputesInReducedPrecisionDifferingIsReducedPrecision) {
  const std::vector<Verdict> v = mediump_group(wrong(), good(), true);
  EXPECT_EQ(v[1].attribution, Attribution::reduced_precision) << v[1].reason;
  EXPECT_EQ(v[1].reason, "glsl on gl/glsl computes in reduced precision what the shader declares so (mediump, "
                         "lowp); every render at full precision passes (glsl vulkan/spirv, glsl gl/spirv, glsl "
                         "gl/cross)");
  EXPECT_STREQ(to_string(v[1].attribution), "reduced precision");
  // The same difference on a path that computes in full precision is the driver's.
  EXPECT_EQ(mediump_group(wrong(), good(), false)[1].attribution, Attribution::driver);
  // A full-precision path failing too: precision does not explain the group.
  const std::vector<Verdict> all = mediump_group(wrong(), wrong(), true);
  EXPECT_NE(all[1].attribution, Attribution::reduced_precision) << all[1].reason;
}

}  // namespace
}  // namespace shaderbed
