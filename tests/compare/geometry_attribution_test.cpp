// Renders whose coverage is wrong the way a matrix mistake makes it (blank, mirrored,
// transposed, misplaced): the verdict names the matrix convention as the likely cause;
// a render with the right coverage and wrong colours says nothing about matrices.
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

// An off-centre disc (so mirroring moves it) as the reference.
ReferenceImage reference() { return disc_reference(10, 18, 40); }

std::vector<Verdict> verdicts_for(const std::vector<Image>& renders, const ReferenceImage& ref) {
  std::vector<RenderOutcome> outcomes;
  const char* paths[] = {"spirv", "spirv", "cross"};
  const char* backends[] = {"vulkan", "gl", "gl"};
  for (size_t i = 0; i < renders.size(); ++i)
    outcomes.push_back({"hlsl", backends[i % 3], paths[i % 3], compare_images(renders[i], ref, kThresholds).pass,
                        &renders[i]});
  return attribute_failures(outcomes, ref, kThresholds);
}

void expect_matrix_verdicts(const std::vector<Image>& renders, const std::string& what) {
  const ReferenceImage ref = reference();
  for (const Verdict& v : verdicts_for(renders, ref)) {
    EXPECT_EQ(v.attribution, Attribution::matrix_convention) << v.reason;
    EXPECT_NE(v.reason.find(what), std::string::npos) << v.reason;
    EXPECT_NE(v.reason.find("row-vector shader (mul(v, M)) given a column-vector matrix"), std::string::npos) << v.reason;
  }
}

TEST(GeometryAttribution, ABlankRenderNamesTheMatrixConvention) {
  const Image blank(kSize, kSize);
  expect_matrix_verdicts({blank, blank, blank}, "blank: the render draws nothing where the reference covers");
  EXPECT_STREQ(to_string(Attribution::matrix_convention), "matrix convention");
}

TEST(GeometryAttribution, MirroredAndTransposedCoverageIsRecognised) {
  const Image left_right = disc_render(10, 64 - 18, 40);
  expect_matrix_verdicts({left_right, left_right, left_right}, "mirrored left-right");
  const Image top_bottom = disc_render(10, 18, 64 - 40);
  expect_matrix_verdicts({top_bottom, top_bottom, top_bottom}, "mirrored top-bottom");
  const Image transposed = disc_render(10, 40, 18);
  const ReferenceImage ref = reference();
  EXPECT_NE(coverage_geometry_evidence(transposed, ref).find("transposed"), std::string::npos)
      << coverage_geometry_evidence(transposed, ref);
}

TEST(GeometryAttribution, AMisplacedShapeIsNamedToo) {
  const Image elsewhere = disc_render(4, 50, 8);
  expect_matrix_verdicts({elsewhere, elsewhere, elsewhere}, "the geometry is misplaced");
}

TEST(GeometryAttribution, RightCoverageWithWrongColoursSaysNothingOfMatrices) {
  const Image wrong = disc_render(10, 18, 40, kSize, [](double v, int) { return v + 0.1; });
  EXPECT_EQ(coverage_geometry_evidence(wrong, reference()), "");
  for (const Verdict& v : verdicts_for({wrong, wrong, wrong}, reference())) {
    EXPECT_NE(v.attribution, Attribution::matrix_convention) << v.reason;
    EXPECT_EQ(v.reason.find("matrix"), std::string::npos) << v.reason;
  }
}

TEST(GeometryAttribution, AStageVerdictKeepsItsStageAndGainsTheEvidence) {
  // Only the cross path is blank: still the cross-compiler, with the matrix note added.
  const ReferenceImage ref = reference();
  const Image good = copy_of(ref), blank(kSize, kSize);
  const std::vector<Verdict> v = verdicts_for({good, good, blank}, ref);
  EXPECT_EQ(v[2].attribution, Attribution::cross_compiler) << v[2].reason;
  EXPECT_NE(v[2].reason.find("blank: the render draws nothing"), std::string::npos) << v[2].reason;
  EXPECT_EQ(v[0].attribution, Attribution::none);
}

}  // namespace
}  // namespace shaderbed
